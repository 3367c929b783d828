#pragma once
// Concealed-effect recordings of a glider for proving the model check: the
// steady-glide model of core/analysis (its own bracketing angle-of-attack
// solver, not the model check's tables) flown forward in time through a
// stratified water column with a heaving thermocline, internal-wave vertical
// velocity noise, buoyancy-engine and pitch transients at the inflections,
// sensor noise, a ballast error, and one or more "truth" effects the
// analysis model may lack: hull compressibility and thermal expansion beyond
// the profile's, mass drift, a pitch-sensor bias, a depth-sensor offset and a
// vertical current. A glide that stalls aborts the mission as a glider does.
// The result is a MissionLog in the interchange format with the truth in its
// metadata (truth_abort_time_s when the mission aborted).
#include <cstdint>
#include <vector>

#include "analysis/glider_flight.h"
#include "missionlog/mission_log.h"

namespace auv::discrepancy {

struct SyntheticGliderTruth {
  // Mass, wing area, lift slope, Cd1, and the TRUE hull compressibility and
  // thermal expansion (reference temperature included).
  analysis::GliderFlightConstants constants;
  double Cd0 = 0.15;
  double net_buoyancy_kg = 0.08;  // rho V - m with the pump at zero, at the reference depth (mean water)
  double reference_depth_m = 75.0;
  double mass_drift_kg_per_h = 0.0;  // mass(t) = m + rate (t - t_mid)
  double pitch_bias_deg = 0.0;       // logged pitch = true + bias
  double depth_offset_m = 0.0;       // logged depth = true + offset
  double vertical_current_mps = 0.0; // upwelling positive
};

struct SyntheticGliderMission {
  int yos = 10;
  double max_depth_m = 150.0;
  double surface_s = 120.0;
  std::vector<double> pump_dive_cm3 = {-250.0};   // cycled over the yos
  std::vector<double> pump_climb_cm3 = {250.0};  // cycled over the yos
  std::vector<double> pitch_dive_deg = {-26.0}, pitch_climb_deg = {24.0};  // cycled over the yos
  double pitch_wander_deg = 1.0;       // AR(1) wander of the true pitch about its set point
  double pitch_time_constant_s = 15.0;
  double pump_rate_cm3_per_s = 10.0;
  // The glider's stall abort (Slocum "no depth change", Seaglider's
  // equivalent): a dive or climb that makes less than this progress in this
  // long aborts the mission: pump to abort_pump_cm3, climb to the surface,
  // and the log ends there (or when the abort climb stalls too). Without it
  // the steady-glide truth would hover for hours with w = 0, which no glider
  // does, and the log would end hours after its last glide.
  double stall_abort_s = 600.0;
  double stall_min_progress_m = 5.0;
  double abort_pump_cm3 = 300.0;
  // Water: tanh thermocline whose depth heaves from yo to yo (internal waves).
  double surface_temperature_degC = 18.0, deep_temperature_degC = 8.0;
  double surface_salinity_psu = 34.6, deep_salinity_psu = 35.2;
  double thermocline_depth_m = 50.0, thermocline_width_m = 12.0, thermocline_heave_m = 15.0;
  double internal_wave_sigma_mps = 0.008, internal_wave_tau_s = 60.0;
  // Logging and noise (1 sigma).
  double step_s = 0.5;
  double sample_interval_s = 1.0;
  double pressure_noise_dbar = 0.02, depth_noise_m = 0.02, pitch_noise_deg = 0.1;
  double temperature_noise_degC = 0.002, salinity_noise_psu = 0.003, pump_noise_cm3 = 0.5;
  double latitude_deg = 45.0;
  std::uint64_t seed = 1;
};

MissionLog synthesizeGliderLog(const SyntheticGliderTruth& truth, const SyntheticGliderMission& mission);

}  // namespace auv::discrepancy
