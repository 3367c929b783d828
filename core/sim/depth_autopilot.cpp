#include "sim/depth_autopilot.h"

#include <algorithm>
#include <cmath>

#include "common/units.h"
#include "sim/actuator_forces.h"

namespace auv::sim {
namespace {

// Keep k_i * integral within +-limit: the integral alone never asks for more
// than the actuator can give.
void clampIntegral(double& integral, double ki, double limit) {
  if (ki == 0.0) return;
  const double bound = std::abs(limit / ki);
  integral = std::clamp(integral, -bound, bound);
}

}  // namespace

double thrusterWeight(double u, const DepthAutopilotConfig& c) {
  return 1.0 - 0.5 * (std::tanh((u - c.u_th_mid_mps) / c.u_th_width_mps) + 1.0);
}

double planeWeight(double u, const DepthAutopilotConfig& c) {
  return 0.5 * (std::tanh((u - c.u_s_mid_mps) / c.u_s_width_mps) + 1.0);
}

DepthAutopilot::DepthAutopilot(const DepthAutopilotConfig& config, const VehicleModel& model)
    : cfg_(config), model_(&model) {}

void DepthAutopilot::reset() {
  int_z_ = int_cr_ = int_plane_ = 0.0;
  out_ = {};
}

void DepthAutopilot::preloadHoverIntegrator(double net_buoyancy_n) {
  if (cfg_.hover_force.ki != 0.0) int_z_ = cfg_.hover_preload_factor * net_buoyancy_n / cfg_.hover_force.ki;
}

ActuatorDemand DepthAutopilot::update(const Measurement& m, const Setpoint& sp, double rho) {
  const VehicleModel& v = *model_;
  const double dt = cfg_.sample_time_s;
  const bool has_thrusters = v.thruster_count >= 2;
  const double w_th = has_thrusters ? thrusterWeight(m.speed_mps, cfg_) : 0.0;
  const double w_s = planeWeight(m.speed_mps, cfg_);
  const double z_err = sp.depth_m - m.depth_m;
  // Sec. 4.1.1: integrate only once the error is small and the depth is not
  // already changing fast.
  const bool freeze = cfg_.anti_windup &&
                      (std::abs(z_err) > cfg_.aw_depth_error_m || std::abs(m.depth_rate_mps) > cfg_.aw_depth_rate_mps);
  ActuatorDemand d;
  d.prop_demand = sp.prop_demand;
  out_.w_thrusters = w_th;
  out_.w_planes = w_s;

  // Eq. 22 and eq. 26 share one integral of the depth error: whatever net
  // buoyancy the thrusters have learnt to carry becomes the pitch bias of the
  // planes, so the hand-over between strategies starts from a consistent state.
  if (!freeze) int_z_ += z_err * dt;

  // Eq. 26, faded in with the plane weight: one pitch demand for both
  // strategies. At rest it is the set pitch (level: an unbalanced pair of
  // thrusters would pitch the vehicle and drive it fore or aft, sec. 4.1);
  // in flight it carries the bias that lets hull lift hold the buoyancy, and
  // the thrusters and planes steer to the same attitude in between.
  const double bias = std::clamp(cfg_.pitch_bias.kp * z_err + cfg_.pitch_bias.ki * int_z_ +
                                     cfg_.pitch_bias.kd * m.depth_rate_mps,
                                 -cfg_.pitch_bias_max_rad, cfg_.pitch_bias_max_rad);
  const double theta_d = sp.pitch_is_demand ? sp.pitch_rad : sp.pitch_rad + w_s * bias;
  const double theta_err = theta_d - m.pitch_rad;

  if (has_thrusters) {
    const double Z = cfg_.hover_force.kp * z_err + cfg_.hover_force.ki * int_z_ + cfg_.hover_force.kd * m.depth_rate_mps;
    // The pitch loops learn only in proportion to the weight of their
    // actuators, so an idle loop does not wind up against the active one.
    int_cr_ += w_th * theta_err * dt;
    clampIntegral(int_cr_, cfg_.hover_cr.ki, cfg_.cr_shift_max_m);
    const double dcr = std::clamp(cfg_.hover_cr.kp * theta_err + cfg_.hover_cr.ki * int_cr_ +
                                      cfg_.hover_cr.kd * m.pitch_rate_radps,
                                  -cfg_.cr_shift_max_m, cfg_.cr_shift_max_m);
    // Eq. 24 as a lever rule about the virtual centre of rotation: Z acts at
    // x_cr. Shifting x_cr aft loads the aft thruster and pitches nose up when
    // Z pushes down; for an upward Z the shift direction flips.
    const TunnelThruster& f = v.thrusters[0];
    const TunnelThruster& a = v.thrusters[1];
    const double x_cr = std::clamp(cfg_.cr0_x_m - (Z >= 0.0 ? dcr : -dcr), a.x_m, f.x_m);
    const double span = f.x_m - a.x_m;
    const double T_front = Z * (x_cr - a.x_m) / span;
    const double T_aft = Z * (f.x_m - x_cr) / span;
    d.thruster_rpm[0] = thrusterRpmForForce(f, rho, w_th * T_front);
    d.thruster_rpm[1] = thrusterRpmForForce(a, rho, w_th * T_aft);
    out_.hover_force_n = Z;
  }

  const double plane_max = units::degToRad(v.planes.max_deg);
  int_plane_ += w_s * theta_err * dt;
  clampIntegral(int_plane_, cfg_.plane.ki, plane_max);
  const double delta = std::clamp(cfg_.plane.kp * theta_err + cfg_.plane.ki * int_plane_ + cfg_.plane.kd * m.pitch_rate_radps,
                                  -plane_max, plane_max);
  d.plane_rad = w_s * delta;
  out_.pitch_cmd_rad = theta_d;
  return d;
}

}  // namespace auv::sim
