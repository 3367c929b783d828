#include "sim/power_model.h"

#include <cmath>

#include "common/units.h"
#include "sim/actuator_forces.h"

namespace auv::sim {
namespace {

double thrusterPower(const PowerModel& p, double rpm) {
  if (rpm == 0.0) return p.thruster_idle_w;
  const double n = std::abs(rpm);
  return p.thruster_idle_w + p.thruster_w_per_rpm3 * n * n * n;
}

}  // namespace

PowerBreakdown electricalPower(const VehicleModel& m, const ActuatorState& a, double u) {
  PowerBreakdown b;
  b.hotel_w = m.power.hotel_w;
  b.prop_w = m.power.prop_w_per_rps2 * a.prop_rps * a.prop_rps;
  for (int i = 0; i < m.thruster_count; ++i) b.thruster_w[i] = thrusterPower(m.power, a.thruster_rpm[i]);
  b.fins_w = m.power.fins_idle_w + m.power.fins_w_per_m2s2_deg * u * u * std::abs(units::radToDeg(a.plane_rad));
  b.total_w = b.hotel_w + b.prop_w + b.thruster_w[0] + b.thruster_w[1] + b.fins_w;
  return b;
}

double hoverHoldPowerW(const VehicleModel& m, double net_buoyancy_n, double rho, double x_cr) {
  if (m.thruster_count < 2) return 0.0;
  const TunnelThruster& f = m.thrusters[0];
  const TunnelThruster& a = m.thrusters[1];
  const double span = f.x_m - a.x_m;
  const double T_front = net_buoyancy_n * (x_cr - a.x_m) / span;
  const double T_aft = net_buoyancy_n * (f.x_m - x_cr) / span;
  double total = 0.0;
  for (double n : {thrusterRpmForForce(f, rho, T_front), thrusterRpmForForce(a, rho, T_aft)}) {
    total += thrusterPower(m.power, n);
  }
  return total;
}

}  // namespace auv::sim
