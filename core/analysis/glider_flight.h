#pragma once
// Steady-glide flight model of an underwater glider (Merckelbach et al. 2010,
// the steady-state model of gliderflight) and its calibration on a log. The
// net buoyancy is parameterised directly, so the fit returns the number the
// technician needs:
//   V(p, T)  = V0 (1 - kappa p) (1 + alpha_T (T - T0)) + V_pump
//   F_B      = g (rho V - m)                        (up positive)
//   lift     = q S a alpha,  drag = q S (Cd0 + Cd1 alpha^2),  q = rho U^2 / 2
//   alpha    from  alpha = (Cd0 + Cd1 alpha^2) / (a tan(alpha + |theta|))
//   U^2      = 2 F_B sin(theta + alpha) / (rho S (Cd0 + Cd1 alpha^2))
//   w        = U sin(theta + alpha)                  (up positive)
// and V0 = (m + nb) / (rho_ref f(p_ref, T_ref)), so that nb is the net
// buoyancy in kg at the reference (operating) state with the pump at zero.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace auv::analysis {

// Hydrodynamic form of the steady glide: the Slocum form above (gliderflight)
// or the Seaglider form of Eriksen et al. 2001 as basestation's hydro_model
// uses it: lift = hd_a alpha q l^2, drag = (hd_b q^hd_s + hd_c alpha^2) q l^2,
// alpha in degrees, q = rho0 U^2 / 2. For the Seaglider form the fitted drag
// parameter (called Cd0 in the fits) is hd_b.
enum class GlideForm { kSlocum, kSeaglider };

struct GliderFlightConstants {
  GlideForm form = GlideForm::kSlocum;
  double hd_a_per_deg = 0.0, hd_c_per_deg2 = 0.0, hd_s = -0.25, hull_length_m = 1.8, rho0_kgm3 = 1027.5;
  double drag_start = 0.15;  // starting value of the fitted drag parameter (Cd0, or hd_b)
  double mass_kg = 0.0;
  double wing_area_m2 = 0.1;             // S (gliderflight default)
  double lift_slope_per_rad = 7.53;      // a = a_w + a_h = 3.73 + 3.8 (gliderflight, AR 7, 43 deg sweep)
  double induced_drag_per_rad2 = 10.5;   // Cd1 (gliderflight: a_w^2/(pi e AR) + 9.7)
  double compressibility_per_dbar = 5e-6;  // kappa (gliderflight epsilon 5e-10 1/Pa)
  double thermal_expansion_per_degC = 0.0;
  double reference_temperature_degC = 20.0;
  // Applied to the logged pitch before use: theta = scale * pitch + offset
  // (e.g. the comet tilt correction 0.86, -0.004 rad).
  double pitch_scale = 1.0;
  double pitch_offset_rad = 0.0;
};

// One observation on the time base of the depth-rate source.
struct GlideSample {
  double pitch_rad = 0.0;      // as logged (the correction is applied by the model)
  double density_kgm3 = 0.0;   // in situ
  double pressure_dbar = 0.0;
  double temperature_degC = 0.0;
  double pump_m3 = 0.0;        // buoyancy engine volume relative to its zero reference
  double w_obs_mps = 0.0;      // observed vertical speed, up positive
  int block = 0;               // glide segment it belongs to (for jackknife and autocorrelation)
};

struct ReferenceState {
  double density_kgm3 = 0.0;
  double pressure_dbar = 0.0;
  double temperature_degC = 0.0;
};

// Angle of attack (rad, same sign as the pitch) for a pitch (rad) and Cd0.
double steadyAngleOfAttack(const GliderFlightConstants& c, double pitch_rad, double Cd0);
// |alpha| for a glide path |phi| (> 0) by Newton from `start`, a root at a
// nearby angle (continuation along a table); bracketing fallback.
double steadyAngleOfAttackNear(const GliderFlightConstants& c, double phi_abs_rad, double Cd0, double start);

// Model vertical speed (up positive) for net buoyancy nb_kg at `ref`; 0 when
// the net force cannot drive a glide in the pitched direction.
double steadyGlideVerticalSpeed(const GliderFlightConstants& c, const ReferenceState& ref, double nb_kg,
                                double Cd0, const GlideSample& s);

// Seaglider form: vertical speed (up positive) for a net buoyancy force
// FB_N (up positive) at pitch theta_rad; 0 when stalled or FB opposes the pitch.
double seagliderVerticalSpeed(const GliderFlightConstants& c, double FB_N, double theta_rad, double hd_b);

// Hull volume at zero pump and zero pressure, reference temperature.
double hullVolumeForNetBuoyancy(const GliderFlightConstants& c, const ReferenceState& ref, double nb_kg);

struct GliderFitOptions {
  double Cd0_start = 0.15;
  std::size_t max_samples = 20000;  // evenly decimated beyond this
  std::size_t max_jackknife_groups = 20;
  int max_iterations = 50;
};

struct GliderFitResult {
  bool converged = false;
  double net_buoyancy_kg = 0.0;
  double net_buoyancy_sigma_kg = 0.0;
  double sigma_ar1_kg = 0.0;        // from the residuals with an AR(1) effective size
  double sigma_jackknife_kg = 0.0;  // delete-one-group jackknife over glide segments
  double Cd0 = 0.0;
  double Cd0_sigma = 0.0;
  double hull_volume_m3 = 0.0;      // V0 at p = 0, T0, pump 0
  double rms_start_mps = 0.0;       // at nb = 0, Cd0 = Cd0_start
  double rms_mps = 0.0;
  double residual_lag1 = 0.0;
  std::size_t samples = 0;
  std::size_t groups = 0;
  std::string message;  // why it did not converge
};

GliderFitResult fitSteadyGlide(std::span<const GlideSample> samples, const GliderFlightConstants& c,
                               const ReferenceState& ref, const GliderFitOptions& options = {});

}  // namespace auv::analysis
