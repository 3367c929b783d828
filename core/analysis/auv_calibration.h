#pragma once
// Joint identification of an AUV's hydrodynamics and its ballast state from
// steady level flight (issue 11 items 1, 2, 4). The steady balance of
// auv_steady_model.h is linear in these named groups once the elevator zero
// offset is carried as c = s_e e0:
//
//   heave: (dB + dB_i) cc = s_Z kZw_i |u| w + s_cf Z_ww |w| w + s_e Z_e u|u| e - c Z_e u|u|
//   pitch: W (BG sin(theta) + x_G cc) = m_uw (rho_i / rho) u w + s_cf M_ww |w| w + s_e M_e u|u| e - c M_e u|u|
//
// with dB the net buoyancy at the reference water, dB_i the known change of
// buoyancy at segment i (in-situ density and hull law), m_uw = 0.5 rho L^3
// M_w' + munk (X_udot - Z_wdot) the whole linear pitch moment (M_w and the
// Munk moment are one term in w, so only their sum can be identified).
// Each group has a prior from the profile (pseudo-observations), so the
// posterior is a generalised least-squares solution with an exact Gaussian
// covariance. Speeds separate gravity (constant) from lift (u^2); depths add
// known buoyancy changes that scale the heave response; BG sets the scale of
// the pitch moments. What the log does not constrain stays at its prior and
// keeps its prior width in the sigmas of net buoyancy and CG x.
#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "analysis/auv_steady_model.h"
#include "analysis/calibration_parameter.h"

namespace auv::analysis {

struct CalibrationPriors {
  double group_rel_sigma = 0.30;  // every derivative group (--coefficient-sigma overrides)
  // Munk moment factor: 1 = on top of M_w, 0 = inside it. A profile that does
  // not say which gets 0.5 +- 0.5.
  double munk_factor = 0.5, munk_sigma = 0.5;
  double elevator_offset_sigma_deg = 2.0;
  double bg_m = 0.02, bg_sigma_m = 0.005;
  // The hull law's two constants (issue 11): the profile's values, and
  // priors on the vehicle's. A HUGIN-class hull's compressibility (foam,
  // free-flooded sections) and thermal expansion are rarely measured: the
  // sigmas are what an unmeasured hull's may plausibly be off by (a foam
  // hull's kappa 3-10e-6 1/dbar, aluminium's alpha 7e-5 1/degC). Each
  // segment's levers (hull_law_levers.h) let the depths and waters flown
  // narrow them.
  double compressibility_per_dbar = 0.0, thermal_expansion_per_degC = 0.0;
  double compressibility_sigma_per_dbar = 5e-6, thermal_expansion_sigma_per_degC = 1e-4;
  // A mass change over the mission (water uptake of the foam, fouling, a lost piece).
  double mass_drift_sigma_kg_per_h = 0.1;
  // The fitted buoyancy laws replace the profile's only at this chi2 of the
  // three (3 dof, 99 %); below it the profile's laws are held.
  double buoyancy_law_chi2 = 11.34;
  // Where the legs scatter less than their propagated standard errors say
  // (chi2/dof < 1, at least 3 degrees of freedom, no history segment), the
  // data information is scaled by the one-sided 95 % upper bound of that
  // variance, never by more than 1 / kMinDataVarianceScale.
  bool narrow_to_scatter = true;
  // A pitch sensor bias the laws must stand beside (the nuisance of their
  // significance test only): an AHRS's mounting is rarely known to better
  // than a degree on a vehicle nobody has aligned.
  double pitch_sensor_bias_sigma_deg = 1.0;
  // The prior on the pitch sensor's bias (reading minus true) carried as a
  // parameter of the ballast state's posterior (0 = the sensor is aligned):
  // the most likely bias is taken out of every segment first, then its
  // remaining uncertainty is marginalised into net buoyancy and CG x
  // (docs/decisions/analysis-pitch-alignment.md).
  double pitch_alignment_sigma_deg = 1.0;
};

// One steady segment: speed, pitch rad, roll rad, elevator deg, depth rate
// and their standard errors, with its water.
struct CalibrationSegment {
  std::array<double, 5> v{}, se{};
  double density_kgm3 = 1025.0;
  double buoyancy_change_n = 0.0;  // B_i - B_reference from density and hull law (known)
  std::optional<BalanceRegressors> regressors;  // an averaged leg's cycle means; unset = from the means v
  // A steady dive or climb (kGlide): kept only where the other legs'
  // calibration explains it (calibrateSteady, glides_dropped).
  bool glide = false;
  // A segment of an earlier mission of the same configuration (history,
  // issue 11 item 3): its weight, and the known moment of the pieces moved
  // since, W_now x_now = W_then x_then + moment, so moment_offset_nm = -moment.
  // Its known mass change is inside buoyancy_change_n.
  double weight_n = 0.0;  // 0 = the current mission's
  double moment_offset_nm = 0.0;
  // d buoyancy_change_n / d kappa [N dbar], / d alpha [N degC] and / d drift
  // [N per kg/h: -g hours from the log's reference time] (0 = none).
  double compressibility_lever_n = 0.0, thermal_lever_n = 0.0, drift_lever_n = 0.0;
};

// kPitchDamping (M_q scale) only acts in the transients; steady legs leave it at its prior.
// The buoyancy laws last (kCompressibility on): the vehicle's hull law minus
// the profile's, and its mass drift in kg/h.
enum CalibrationIndex {
  kNet = 0, kXg, kHeave, kPitchUw, kCrossflow, kPlanes, kPlaneOffset, kBg, kPitchDamping,
  kCompressibility, kThermalExpansion, kMassDrift, kCalibrationCount
};

// Whitened output-error residuals of the log's transients at the parameters
// p (auv_transient_fit.h); empty = steady legs only.
// group_ends: where each window's residuals end (for the jackknife over
// windows that measures how far the windows disagree).
struct TransientResiduals {
  std::function<Eigen::VectorXd(const Eigen::VectorXd& p)> residuals;
  std::vector<Eigen::Index> group_ends;
  std::function<void(const Eigen::VectorXd& p)> reweight;  // optional: channel sigmas from the misfit at p
  explicit operator bool() const { return static_cast<bool>(residuals) && !group_ends.empty(); }
};

struct SteadyCalibration {
  bool ok = false;
  Eigen::VectorXd p;    // CalibrationIndex order; net in N, x_G and BG in m, c in deg
  Eigen::MatrixXd cov;
  // The segments' measurement covariance is the expectation over the prior
  // (mean weights_at, sigmas weights_sigma) of the parameter-dependent one.
  Eigen::VectorXd weights_at, weights_sigma;
  double chi2_per_dof = 0.0;
  // The scale the steady rows' variance was given: chi2/dof above 1, the
  // one-sided 95 % upper bound of it below 1 (CalibrationPriors::
  // narrow_to_scatter), 1 = as propagated. Planned legs (covarianceAfter)
  // are weighed with it too.
  double data_variance_scale = 1.0;
  double data_parameters = 0.0;  // effective number of parameters the data determined
  std::vector<CalibrationParameter> parameters;  // hydrodynamic groups only
  double elevator_offset_deg = 0.0, elevator_offset_sigma_deg = 0.0;
  // Transients (when given): residual count, chi2 per residual at the
  // optimum and the factor their information was divided by.
  std::size_t transient_residuals = 0;
  double transient_chi2_per_residual = 0.0, transient_inflation = 1.0;
  double transient_jackknife_net_sigma_n = 0.0;  // the windows' scatter, added to the posterior
  double transient_net_sigma_n = 0.0;            // net buoyancy sigma with the transients
  // false: with their scatter the transients knew less than the steady
  // segments (a wider net buoyancy or CG x sigma), and p, cov are the steady ones.
  bool transients_kept = false;
  // Glides the other legs' calibration could not explain (chi2 of the
  // prediction from every other kept segment above 13.8, 2 dof, 99.9 %):
  // pitch held flat while the depth changes is not always a steady balance.
  // Left out of the fit.
  std::size_t glides_dropped = 0;
  std::vector<bool> segment_kept;  // per input segment: false for those glides
  // The buoyancy laws' change from the profile's, free: its chi2 from zero,
  // and whether it was significant and so used (else the profile's are held).
  double buoyancy_law_chi2 = 0.0;
  double buoyancy_law_chi2_with_pitch_bias = 0.0;  // the same with a pitch sensor bias free beside them
  // The pitch sensor bias (reading minus true) carried beside the groups
  // (CalibrationPriors::pitch_alignment_sigma_deg), deg; sigma 0 = not carried.
  double pitch_sensor_bias_deg = 0.0, pitch_sensor_bias_sigma_deg = 0.0;
  bool buoyancy_law_fitted = false;
  // Fitted: the one law (0 compressibility, 1 thermal expansion, 2 mass
  // drift) that alone explains the legs about as well as the three; the
  // others are held at the profile's. -1: the three, or none.
  int single_buoyancy_law = -1;
  // Another law that alone explains the legs within 2 of the chosen one's
  // chi-square rise (a likelihood ratio above 0.37): the log cannot tell
  // them apart, and the chosen law's parameter names it (`rival`). -1: none.
  int rival_buoyancy_law = -1;
};

// Nominal linear pitch-moment derivative m_uw at density rho for a Munk factor.
double pitchMomentUw(const SteadyHydroCoefficients& c, double rho, double munk_factor);

SteadyCalibration calibrateSteady(const SteadyHydroCoefficients& c, double weight_n, double rho_ref,
                                  const std::vector<CalibrationSegment>& segments, const CalibrationPriors& priors,
                                  const TransientResiduals& transients = {});

// The posterior covariance after adding planned steady segments (a short
// calibration manoeuvre) to the log: posterior information plus the planned
// segments' Fisher information of the same model at the calibrated values.
Eigen::MatrixXd covarianceAfter(const SteadyHydroCoefficients& c, double weight_n, double rho_ref,
                                const SteadyCalibration& cal, const std::vector<CalibrationSegment>& planned);

// Steady hydrodynamic loads with the calibrated groups (for prediction).
SteadyHydroCoefficients calibratedCoefficients(const SteadyHydroCoefficients& c, double rho_ref,
                                               const Eigen::VectorXd& p);

}  // namespace auv::analysis
