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

#include "analysis/analysis_options.h"
#include "analysis/analysis_report.h"
#include "analysis/auv_trim_estimation.h"
#include "analysis/glider_flight.h"
#include "analysis/glider_target.h"
#include "analysis/profile_constants.h"
#include "analysis/segments.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis {

// An analysed mission as history: its steady segments, the pieces installed
// then, and the biases its analysis took out.
inline HistoryMission historyMissionOf(const AnalysisReport& r, std::vector<double> installed_kg) {
  return {r.steady_segments, std::move(installed_kg), r.pitch_bias_removed_deg, r.roll_bias_removed_deg};
}

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
