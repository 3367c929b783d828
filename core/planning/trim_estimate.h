#pragma once
// What a post-mission analysis found about the vehicle as it flew: net
// buoyancy and CG offset with their 1-sigma uncertainties, and the water in
// which they hold. The net buoyancy is only meaningful together with that
// water (density, temperature, pressure): the planner turns it into a mass
// with rho_log V(T_log, p_log) and never reuses the number in other water.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "hydrostatics/balance.h"

namespace auv {

struct TrimEstimate {
  double net_buoyancy_kg = 0.0;        // B - W at `water`, positive = too light
  double net_buoyancy_sigma_kg = 0.0;  // 1 sigma
  std::optional<double> cg_x_m, cg_y_m;  // CG - CB, body axes; nullopt = not identified
  // Where cg_y_m comes from: "static" (the CG itself) or "cruise" (the CG
  // that would give the roll seen at cruise: propeller torque included, so
  // zeroing it levels the vehicle at cruise rpm, thesis §5.3.3).
  std::string cg_y_basis = "static";
  double cruise_rpm = 0.0;
  double cruise_speed_mps = 0.0;  // 0 = unknown (no flying-pitch prediction)
  double cg_x_sigma_m = 0.0, cg_y_sigma_m = 0.0;
  // BG of the analysed vehicle when measured (roll test); nullopt = the
  // profile's. The cruise CG y is BG sin(roll): the plan's roll must use the same BG.
  std::optional<double> bg_m;
  WaterState water;                    // in situ where net buoyancy was identified
  double salinity_psu = 35.0;
  double depth_m = 0.0;
  // The thesis's post-mission deviations (App. D signs), for the classic table:
  // depth commanded - measured (+ = light), pitch measured - commanded (+ = nose
  // up), roll (+ = starboard down).
  std::optional<double> depth_error_m, pitch_error_deg, roll_deg;
  // The steady hydrodynamics the analysis calibrated from the log (a
  // "hydrodynamics" section: details.auv_estimate.calibrated_hydrodynamics),
  // for the flight-pitch prediction; unset = the profile's.
  std::optional<nlohmann::json> calibrated_hydrodynamics;
  // The analysis's proposed calibration manoeuvre {legs, expected_sigma}.
  std::optional<nlohmann::json> calibration_manoeuvre;
  // The analysis's prediction for the next mission flown after a move and
  // analysed with this log as history (details.auv_estimate.after_move_expected_sigma).
  std::optional<double> after_move_net_sigma_kg, after_move_x_sigma_m;
  // The analysed log's legs not flown as commanded (details.flight_envelope):
  // off the command at an elevator stop, shallower (too light or stern-heavy)
  // or deeper (too heavy or bow-heavy), or porpoising.
  bool log_too_light = false, log_too_heavy = false, log_porpoising = false;
  // The hull law the analysis fitted and used (calibration entries
  // hull_compressibility / thermal_expansion with "used": true): the plan's
  // buoyancy at the next mission's depth and temperature follows it.
  std::optional<double> hull_compressibility_per_dbar, hull_thermal_expansion_per_degC;
  double hull_compressibility_sigma_per_dbar = 0.0, hull_thermal_expansion_sigma_per_degC = 0.0;  // their sigmas
};

// Reads the analysis report JSON (issue #3 contract: net_buoyancy_kg,
// net_buoyancy_sigma_kg, cg_offset_mm {x, y}, cg_offset_sigma_mm, errors,
// water {temperature_degC, salinity_psu, density_kgm3, pressure_dbar,
// depth_m}). A null CG component is "not identified"; a null net buoyancy or
// water throws InputError naming the field, since nothing can be planned
// without them. Missing pressure is derived from depth, missing density
// from T, S and pressure (EOS-80). When the report has cruise.cg_y_mm, CG y
// is that cruise-equivalent value (cg_y_basis "cruise").
TrimEstimate trimEstimateFromReport(const nlohmann::json& report, const std::string& file);

}  // namespace auv
