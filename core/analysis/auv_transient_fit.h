#pragma once
// The transients of a survey log as an output-error problem (issue 11 item
// 2): short windows around each depth-command step and propeller-speed
// change are flown again through the simulator's vertical-plane dynamics
// (sim/dynamics.h) with the logged stern-plane angle and propeller speed,
// from the logged state at the window start, and the simulated pitch and
// depth are compared with the logged ones. The parameters are those of the
// steady calibration (auv_calibration.h, CalibrationIndex order), so the two
// are fitted jointly: the inertia of the vehicle is a known force, which is
// what separates the net buoyancy from the stern-plane effectiveness and the
// CG x that steady legs alone only know as one combination.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "missionlog/mission_log.h"
#include "sim/depth_autopilot.h"
#include "sim/vehicle_model.h"

namespace auv::analysis {

struct TransientFitContext {
  double weight_n = 0.0;          // as flown (profile mass + installed weights)
  double density_ref_kgm3 = 1025.0;  // the calibration's reference water
  double buoyancy_ref_n = 0.0;    // g rho_ref V(T_ref, p_ref): net = B_ref - W
  double extra_Iyy_kgm2 = 0.0;    // of the installed adjustment weights about the CB
  double window_before_s = 15.0, window_after_s = 75.0;
  std::size_t max_windows = 24;  // spread evenly over the log (bounds the time on long logs)
  double min_depth_m = 3.0;      // windows that come shallower are left out (the surface)
  double dt_s = 0.1;             // model step
  // The vehicle's autopilot (profile): its stern-plane loop (eq. 27) tracks
  // the logged pitch command, so the noisy logged elevator is compared as an
  // output instead of driving the model as an input.
  sim::DepthAutopilotConfig autopilot;
};

class TransientFit {
 public:
  // nominal: the profile's simulator model (its hydrodynamic groups are
  // rescaled by the parameters). hull: the volume law V(T, p).
  TransientFit(const MissionLog& log, const sim::VehicleModel& nominal, const TransientFitContext& ctx);

  std::size_t windowCount() const { return windows_.size(); }
  std::size_t residualCount() const { return n_residuals_; }
  // Where each window's residuals end in residuals().
  std::vector<Eigen::Index> windowEnds() const;
  // Whitened residuals (simulated - logged) / sigma of every window, each
  // window's pitch, then depth, then elevator samples in time order.
  Eigen::VectorXd residuals(const Eigen::VectorXd& p) const;
  // The same with a given simulator model (p then sets only the mass
  // properties, the net buoyancy and the elevator offset): a test flies the
  // truth's own model.
  Eigen::VectorXd residualsOf(const sim::VehicleModel& model, const Eigen::VectorXd& p) const;
  // The simulator model the parameters p describe (for tests and plots).
  sim::VehicleModel modelFor(const Eigen::VectorXd& p) const;
  // Each channel's sigma times its root mean square whitened residual at p
  // (never below the noise level it had).
  void rescaleChannels(const Eigen::VectorXd& p);
  double pitchSigmaRad() const { return sigma_pitch_rad_; }
  double depthSigmaM() const { return sigma_depth_m_; }

 private:
  struct Window {
    // Driving values on the model grid and the known buoyancy change (N).
    // Roll is taken from the log (its moments, propeller torque and CG y, are
    // the roll estimate's business, not this fit's).
    std::vector<double> pitch_cmd_rad, prop_rps, buoyancy_change_n, density_kgm3, roll_rad;
    double u0 = 0.0, w0 = 0.0, z0 = 0.0, theta0 = 0.0, phi0 = 0.0;
    std::vector<std::size_t> obs_step;  // model step of each observation
    std::vector<double> obs_pitch_rad, obs_depth_m, obs_elevator_deg;  // NaN = not observed
  };
  void simulate(const Window& w, const sim::VehicleModel& model, const Eigen::VectorXd& p, double* out) const;

  sim::VehicleModel nominal_;
  TransientFitContext ctx_;
  std::vector<Window> windows_;
  std::size_t n_residuals_ = 0;
  double sigma_pitch_rad_ = 0.0, sigma_depth_m_ = 0.0, sigma_elevator_deg_ = 0.0;
};

}  // namespace auv::analysis
