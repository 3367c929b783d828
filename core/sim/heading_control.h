#pragma once
// Heading: the yaw degree of freedom of vehicle_model.h's YawModel and the
// heading-hold loop that drives its rudder. Yaw is decoupled from the
// vertical plane (v = 0, no restoring moment), so it is integrated beside the
// RK4 state rather than inside it: the 3-DOF + roll step stays as fast as it
// was, and a vehicle without heading hold keeps its heading exactly.
#include "sim/depth_autopilot.h"
#include "sim/vehicle_model.h"

namespace auv::sim {

struct YawState {
  double r_radps = 0.0;     // yaw rate
  double heading_rad = 0.0; // 0..2 pi, clockwise from north
  double rudder_rad = 0.0;  // log sign: positive turns the bow to starboard
};

// (I_zz - N_rdot) r_dot = N_r |u| r + N_|r|r |r| r + N_d u |u| delta, with
// the model's constants divided by the inertia once (the step loop calls
// advanceYaw 20 times a second of mission).
struct YawConstants {
  bool active = false;       // false: no yaw model, heading held
  double nr_per_rho_u = 0.0; // 0.5 L^4 N_r' / I  [m^3/kg], times rho |u| = 1/s
  double nrr = 0.0;          // N_|r|r / I
  double nd_per_rad = 0.0;   // N_d (per rad) / I  [1/m^2]
};
YawConstants yawConstants(const VehicleModel& model);

// One step with u, delta, theta, phi, q held: trapezoidal rule on the linear
// damping (A-stable, second order), explicit on the rest; then the Euler
// kinematics psi_dot = (q sin phi + r cos phi) / cos theta. The attitude comes
// as sines/cosines (the integrator has them at the start of the step).
inline void advanceYaw(const YawConstants& k, double rho, double u, double q, double cth, double sph, double cph,
                       double dt, YawState& y) {
  if (!k.active) return;
  const double au = u < 0.0 ? -u : u;
  const double a = k.nr_per_rho_u * rho * au;  // <= 0
  const double r0 = y.r_radps;
  const double f = k.nrr * (r0 < 0.0 ? -r0 : r0) * r0 + k.nd_per_rad * u * au * y.rudder_rad;
  y.r_radps = (r0 * (1.0 + 0.5 * a * dt) + dt * f) / (1.0 - 0.5 * a * dt);
  const double psi = y.heading_rad + dt * (q * sph + 0.5 * (r0 + y.r_radps) * cph) / cth;
  constexpr double kTwoPi = 6.283185307179586;
  y.heading_rad = psi >= kTwoPi ? psi - kTwoPi : (psi < 0.0 ? psi + kTwoPi : psi);
}

// Moves the rudder towards its demand at the rudder's rate limit.
void advanceRudder(const VehicleModel& model, double demand_rad, double dt_s, YawState& yaw);

// Wraps an angle to (-pi, pi].
double wrapPi(double angle_rad);

class HeadingAutopilot {
 public:
  HeadingAutopilot(const HeadingHoldConfig& config, double sample_time_s) : cfg_(config), dt_(sample_time_s) {}
  // Rudder demand [rad] for a heading set point; derivative on the measured
  // yaw rate (PI-D), integral clamped to the rudder limit.
  double update(double heading_set_rad, double heading_rad, double yaw_rate_radps);

 private:
  HeadingHoldConfig cfg_;
  double dt_;
  double integral_ = 0.0;
};

}  // namespace auv::sim
