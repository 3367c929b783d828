#include "sim/heading_control.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/units.h"

namespace auv::sim {

double wrapPi(double a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  a = std::fmod(a, kTwoPi);
  if (a > std::numbers::pi) a -= kTwoPi;
  if (a <= -std::numbers::pi) a += kTwoPi;
  return a;
}

YawConstants yawConstants(const VehicleModel& m) {
  const YawModel& Y = m.yaw;
  const double inertia = Y.Izz_kgm2 - Y.Nrdot_kgm2;
  YawConstants k;
  if (!(inertia > 0.0)) return k;
  const double L2 = m.body.reference_length_m * m.body.reference_length_m;
  k.active = true;
  k.nr_per_rho_u = 0.5 * L2 * L2 * Y.Nr_prime / inertia;
  k.nrr = Y.Nrr_kgm2 / inertia;
  k.nd_per_rad = Y.N_uud_per_deg * units::radToDeg(1.0) / inertia;
  return k;
}

void advanceRudder(const VehicleModel& m, double demand, double dt, YawState& y) {
  const double max_rad = units::degToRad(m.yaw.rudder_max_deg);
  const double target = std::clamp(demand, -max_rad, max_rad);
  const double step = units::degToRad(m.yaw.rudder_rate_deg_per_s) * dt;
  y.rudder_rad += std::clamp(target - y.rudder_rad, -step, step);
}

double HeadingAutopilot::update(double set, double heading, double rate) {
  if (!cfg_.enabled) return 0.0;
  const double e = wrapPi(set - heading);
  const PidGains& g = cfg_.gains;
  if (std::abs(e) < cfg_.integrate_within_rad) integral_ += e * dt_;
  if (g.ki != 0.0) {
    const double bound = std::abs(cfg_.max_rudder_rad / g.ki);
    integral_ = std::clamp(integral_, -bound, bound);
  }
  return std::clamp(g.kp * e + g.ki * integral_ + g.kd * rate, -cfg_.max_rudder_rad, cfg_.max_rudder_rad);
}

}  // namespace auv::sim
