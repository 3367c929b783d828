#pragma once
// Post-mission analysis: segments from the data, errors and water with
// confidence intervals, and the physical estimate of net buoyancy and CG
// offset (AUV steady-flight balance or glider steady-glide fit), plus the
// thesis's classic checks for comparison. Single passes over each channel;
// a 24 h 10 Hz log analyses in a fraction of a second.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/analysis_report.h"
#include "analysis/auv_trim_estimation.h"
#include "analysis/glider_flight.h"
#include "analysis/glider_target.h"
#include "analysis/profile_constants.h"
#include "analysis/segments.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis {

// An earlier analysed mission of the same configuration: its steady
// segments (AnalysisReport::steady_segments) and what was installed then.
struct HistoryMission {
  std::vector<SteadySegmentMeans> segments;
  std::vector<double> installed_kg;
  // The accepted sensor biases its analysis took out of these segments
  // (AnalysisReport::pitch_bias_removed_deg): analyzeMission puts them on
  // the footing of the biases it takes out now, the sensor being the same.
  double pitch_bias_removed_deg = 0.0, roll_bias_removed_deg = 0.0;
};

// An analysed mission as history: its steady segments, the pieces installed
// then, and the biases its analysis took out.
inline HistoryMission historyMissionOf(const AnalysisReport& r, std::vector<double> installed_kg) {
  return {r.steady_segments, std::move(installed_kg), r.pitch_bias_removed_deg, r.roll_bias_removed_deg};
}

struct AnalysisOptions {
  std::string log_name;
  std::vector<double> installed_kg;  // adjustment weight at each profile point during the mission; empty = none given
  std::optional<double> bg_m;        // CG below CB from an inclining/roll test (--bg-mm)
  std::optional<double> target_density_kgm3;  // gliders: same as glider_target.density_kgm3 (kept for callers)
  // Gliders: the next deployment's water (default: the log's own water at
  // the bottom of its deepest yo; analysis/glider_target.h).
  GliderTargetRequest glider_target;
  SegmentOptions segments;           // `glider` is set from the vehicle kind
  // Prior width of each hydrodynamic derivative group in the calibration
  // (--coefficient-sigma); unset = 30 % and an unknown Munk structure.
  std::optional<double> coefficient_rel_sigma;
  // AUVs: prior sigma of the pitch sensor's bias, found from the log beside
  // the ballast state (--pitch-alignment-sigma-deg; 0 = the sensor is
  // aligned and read as true). An AHRS nobody aligned is off by up to a degree.
  double pitch_alignment_sigma_deg = 1.0;
  double bg_profile_rel_sigma = 0.25;
  // Fit the log's transients through the simulator jointly with the steady
  // legs (auv_transient_fit.h) when the profile has the simulator sections
  // and the log has pitch_cmd. Off by default: on the identification bench
  // its 2-sigma coverage is still below 90 % (see README, issue 11).
  bool use_transients = false;
  double default_density_kgm3 = 1025.0;  // only when the log has no CTD
  // Gliders
  double glider_min_depth_m = 10.0;
  double glider_max_depth_m = std::numeric_limits<double>::infinity();
  double glider_min_pitch_deg = 10.0;
  double glider_rate_window_s = 10.0;
  // Attitude-sensor pitch bias (1 sigma) whose effect on the fitted net
  // buoyancy is added to its sigma (the fit cannot see a constant bias).
  double glider_pitch_bias_sigma_deg = 0.5;
  GliderFitOptions glider_fit;
  bool classic = true;
  // AUVs: earlier missions of this configuration; with a known weight change
  // between them they calibrate the hydrodynamics jointly (issue 11 item 3).
  std::vector<HistoryMission> history;
};

// Throws InputError when the log has no usable depth/pressure or `installed_kg`
// does not match the profile's points.
// Attitude sensor biases the profile holds (accepted from a model check) are
// taken out of the log first, their sigmas carried into the ballast state's
// (analysis/attitude_sensor_bias.h).
AnalysisReport analyzeMission(const MissionLog& log, const VehicleProfile& vehicle, const AnalysisOptions& options = {});

namespace detail {
// The analysis of the log's channels as recorded (analyzeMission's core).
AnalysisReport analyzeRecordedLog(const MissionLog& log, const VehicleProfile& vehicle, const AnalysisOptions& options);
}  // namespace detail

// gliderConstantsFromProfile and latitudeFromMetadata: analysis/profile_constants.h.

}  // namespace auv::analysis
