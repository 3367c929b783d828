#pragma once
// A buoyancy-driven glider (Slocum G2) for the simulator: the steady-glide
// force balance of Merckelbach et al. (2010) - the model core/analysis fits -
// with the pitch set by the hydrostatic trim of the moving pitch battery and
// the buoyancy pump (core hydrostatics' staticTrim; the hydrodynamic pitching
// moment is neglected, as in the steady model) and first-order lags for the
// transients at the inflections. Parameters come from the profile's
// "glider_flight" section (docs/decisions/sim-glider.md).
#include <Eigen/Core>

#include "sim/flown_mass.h"
#include "vehicle/vehicle_profile.h"

namespace auv::sim {

struct GliderModel {
  std::string id;
  double mass_kg = 0.0;                               // profile reference mass
  Eigen::Vector3d r_g_m = Eigen::Vector3d::Zero();    // CG - CB, battery at 0
  Eigen::Vector3d cb_profile_m = Eigen::Vector3d::Zero();
  HullModel hull;                 // the profile's, compressibility as in flight
  // Steady glide (gliderflight's Slocum constants unless the profile says).
  double wing_area_m2 = 0.1;
  double lift_slope_per_rad = 7.53;
  double induced_drag_per_rad2 = 10.5;
  double Cd0 = 0.15;
  // Buoyancy engine: +-max about its zero, at x_pump from the CB.
  double pump_max_m3 = 250e-6;
  double pump_rate_m3_per_s = 10e-6;
  double pump_x_m = 0.0;
  // Pitch battery: mass moving +-travel along x (positive = forward).
  double battery_mass_kg = 0.0;
  double battery_travel_m = 0.0;
  double battery_rate_m_per_s = 0.0;
  double pitch_time_constant_s = 10.0;
  double speed_time_constant_s = 10.0;
  // Saw-tooth defaults.
  double dive_pitch_rad = -0.454, climb_pitch_rad = 0.454;
  double control_interval_s = 4.0;
  // Power: hotel, and while the pump or battery motor runs.
  double hotel_w = 0.0, pump_w = 0.0, battery_w = 0.0;
};

// Throws InputError naming the field if the profile has no "glider_flight"
// section or a value is out of range.
GliderModel loadGliderModel(const VehicleProfile& profile);

struct SteadyGlideSolution {
  bool gliding = false;       // false: buoyancy and pitch disagree, no steady glide
  double alpha_rad = 0.0;     // angle of attack, same sign as the pitch
  double speed_mps = 0.0;     // through water, along the path
  double w_up_mps = 0.0;      // U sin(theta + alpha)
};

// alpha = (Cd0 + Cd1 alpha^2) / (a tan(alpha + |theta|)) (smallest root),
// U^2 = 2 |F_B| sin(|theta| + |alpha|) / (rho S (Cd0 + Cd1 alpha^2)).
SteadyGlideSolution steadyGlide(const GliderModel& g, double rho, double net_buoyancy_up_n, double pitch_rad);

// CG - CB and CB shift for a battery position and pump volume; static pitch
// and roll from core hydrostatics' staticTrim.
struct GliderTrim {
  double pitch_rad = 0.0, roll_rad = 0.0;
};
GliderTrim gliderStaticTrim(const GliderModel& g, const FlownMass& mass, double hull_volume_m3, double rho,
                            double battery_m, double pump_m3);
// Battery position that trims to `pitch_rad` (closed form), clamped to the travel.
double batteryForPitch(const GliderModel& g, const FlownMass& mass, double hull_volume_m3, double rho,
                       double pump_m3, double pitch_rad);

}  // namespace auv::sim
