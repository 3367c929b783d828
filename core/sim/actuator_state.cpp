#include "sim/actuator_state.h"

#include <algorithm>
#include <cmath>

#include "common/units.h"
#include "sim/actuator_forces.h"

namespace auv::sim {
namespace {

// Exact first-order lag over one step, then the slew-rate limit.
double lagAndSlew(double x, double target, double alpha, double max_step) {
  const double lagged = target + (x - target) * alpha;
  return x + std::clamp(lagged - x, -max_step, max_step);
}

double lagFactor(double dt, double tau) { return tau > 0.0 ? std::exp(-dt / tau) : 0.0; }

}  // namespace

ActuatorDynamics::ActuatorDynamics(const VehicleModel& model, double dt_s)
    : model_(&model), dt_(dt_s), alpha_prop_(lagFactor(dt_s, model.prop.time_constant_s)) {
  for (int i = 0; i < kMaxThrusters; ++i) {
    alpha_th_[i] = lagFactor(dt_s, model.thrusters[i].time_constant_s);
  }
}

double ActuatorDynamics::thrusterTargetRpm(int i, double demand_rpm) const {
  const TunnelThruster& t = model_->thrusters[i];
  if (std::abs(demand_rpm) < t.deadband_rpm) return 0.0;
  return std::clamp(demand_rpm, -t.max_rpm, t.max_rpm);
}

void ActuatorDynamics::advance(ActuatorState& s, const ActuatorDemand& d) const {
  const VehicleModel& m = *model_;
  const double n_target = propellerRpsFromDemand(m.prop, d.prop_demand);
  s.prop_rps = lagAndSlew(s.prop_rps, n_target, alpha_prop_, m.prop.max_rate_rps_per_s * dt_);

  for (int i = 0; i < m.thruster_count; ++i) {
    const double target = thrusterTargetRpm(i, d.thruster_rpm[i]);
    // A motor inside its deadband does not turn: the lag would otherwise leave
    // it spinning slowly forever below the deadband.
    double n = lagAndSlew(s.thruster_rpm[i], target, alpha_th_[i], 1e12);
    if (target == 0.0 && std::abs(n) < m.thrusters[i].deadband_rpm) n = 0.0;
    s.thruster_rpm[i] = n;
  }

  const double max_rad = units::degToRad(m.planes.max_deg);
  const double target = std::clamp(d.plane_rad, -max_rad, max_rad);
  const double before = s.plane_rad;
  const double max_step = units::degToRad(m.planes.rate_deg_per_s) * dt_;
  s.plane_rad = before + std::clamp(target - before, -max_step, max_step);
  s.plane_rate_radps = (s.plane_rad - before) / dt_;
}

}  // namespace auv::sim
