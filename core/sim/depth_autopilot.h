#pragma once
// The Delphin2 paper's unified diving controller (sec. 4): a hover-style PI-D
// that computes a vertical force and shifts a virtual centre of rotation to
// share it between the tunnel thrusters (eq. 22-25, conditional-integration
// anti-windup of sec. 4.1.1), a flight-style pitch-bias PI-D feeding a
// stern-plane PI-D (eq. 26-27), and tanh weights that fade one into the other
// with forward speed (eq. 28-29). Derivative terms act on the measured state,
// not on the error (PI-D), so the derivative gains are negative.
// A vehicle with no tunnel thrusters (HUGIN) uses the flight half only.
#include "sim/vehicle_model.h"

namespace auv::sim {

struct PidGains {
  double kp = 0.0, ki = 0.0, kd = 0.0;
};

// Heading hold, a PI-D from heading error [rad] to rudder [rad, log sign]
// riding along with the depth autopilot at its sample rate (heading_control.h).
struct HeadingHoldConfig {
  bool enabled = false;  // off: rudder at zero, heading follows the dynamics
  PidGains gains;
  double max_rudder_rad = 0.35;  // the autopilot's own limit, inside the rudder's travel
  // Conditional integration: the integral learns only near the set heading,
  // so a long saturated turn does not wind it up into an overshoot.
  double integrate_within_rad = 0.175;
};

struct DepthAutopilotConfig {
  double sample_time_s = 0.2;  // paper: 5 Hz
  // eq. 22, Z [N] from depth error [m]; eq. 23, centre-of-rotation shift [m]
  // from pitch error [rad], positive aft so that positive shift = nose up.
  PidGains hover_force;
  PidGains hover_cr;
  double cr0_x_m = 0.0;
  double cr_shift_max_m = 0.3;
  bool anti_windup = true;
  double aw_depth_error_m = 0.3;   // freeze the eq. 22 integrator above this |z~|
  double aw_depth_rate_mps = 0.1;  // ... or above this |dz/dt|
  // eq. 26, pitch demand [rad] from depth error [m] (K_P < 0: deeper = nose down).
  PidGains pitch_bias;
  double pitch_bias_max_rad = 0.35;
  // eq. 27, stern-plane angle [rad, paper sign] from pitch error [rad].
  PidGains plane;
  // eq. 28-29
  double u_th_mid_mps = 0.85, u_th_width_mps = 0.03;
  double u_s_mid_mps = 0.5, u_s_width_mps = 0.04;
  double hover_preload_factor = 1.2;  // sec. 7
  HeadingHoldConfig heading;
};

struct Measurement {
  double depth_m = 0.0;
  double depth_rate_mps = 0.0;
  double pitch_rad = 0.0;
  double pitch_rate_radps = 0.0;
  double speed_mps = 0.0;
};

struct Setpoint {
  double depth_m = 0.0;
  double pitch_rad = 0.0;    // hover pitch reference and flight pitch offset
  double prop_demand = 0.0;  // passed through (open-loop speed, as in the paper)
  // Replay of a recorded pitch command: pitch_rad is the whole pitch demand
  // (the depth loop's bias is not added; the planes track it directly).
  bool pitch_is_demand = false;
};

struct ActuatorDemand {
  double prop_demand = 0.0;
  std::array<double, kMaxThrusters> thruster_rpm{};
  double plane_rad = 0.0;  // paper sign
};

// What the controller computed this sample, for the trace.
struct AutopilotOutputs {
  double hover_force_n = 0.0;
  double pitch_cmd_rad = 0.0;  // the pitch the active strategy steers to
  double w_thrusters = 0.0, w_planes = 0.0;
};

class DepthAutopilot {
 public:
  DepthAutopilot(const DepthAutopilotConfig& config, const VehicleModel& model);

  // One controller sample; dt is the time since the previous sample.
  ActuatorDemand update(const Measurement& m, const Setpoint& sp, double water_density_kgm3);
  // Sec. 7: start with the integrator at `factor` x the force that holds the
  // given net buoyancy, so the vehicle dives at once from the surface.
  void preloadHoverIntegrator(double net_buoyancy_n);
  void reset();

  const AutopilotOutputs& outputs() const { return out_; }
  double hoverIntegralN() const { return cfg_.hover_force.ki * int_z_; }

 private:
  DepthAutopilotConfig cfg_;
  const VehicleModel* model_;
  double int_z_ = 0.0;      // integral of depth error, shared by eq. 22 and 26
  double int_cr_ = 0.0;     // integral of pitch error, eq. 23
  double int_plane_ = 0.0;  // integral of pitch error, eq. 27
  AutopilotOutputs out_;
};

// Eq. 28-29.
double thrusterWeight(double u_mps, const DepthAutopilotConfig& c);
double planeWeight(double u_mps, const DepthAutopilotConfig& c);

}  // namespace auv::sim
