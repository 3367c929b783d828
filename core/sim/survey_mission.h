#pragma once
// Realistic survey missions for proving the analysis (issue 11): 2-4 h of
// survey lines at 2-3 propeller speeds and 2-3 depths with a few depth steps
// and turns between lines, in stratified water with an internal wave, logged
// with realistic sensor noise; drop-outs are applied to the log afterwards.
// Deterministic per seed.
#include <cstdint>
#include <string>
#include <vector>

#include "missionlog/mission_log.h"
#include "sim/simulator.h"
#include "sim/water_column.h"

namespace auv::sim {

struct SurveyRanges {
  double duration_min_s = 2.0 * 3600.0, duration_max_s = 4.0 * 3600.0;
  int speeds_min = 2, speeds_max = 3;
  int depths_min = 2, depths_max = 3;
  double rpm_min = 110.0, rpm_max = 190.0, rpm_spacing = 20.0;
  // Shallow enough that the band at depth and a floating vehicle at the
  // surface can both hold with an incompressible hull (planning-safety-margin.md).
  double depth_min_m = 20.0, depth_max_m = 90.0, depth_spacing_m = 15.0;
  double line_min_s = 600.0, line_max_s = 1500.0;
  double trace_interval_s = 1.0;
};

struct SurveyMission {
  Scenario scenario;  // legs and initial state; the caller adds installed weights and ballast error
  std::vector<CtdPoint> cast;
  double internal_wave_amplitude_m = 0.0, internal_wave_period_s = 0.0;
  double latitude_deg = 60.0;  // a Norwegian fjord or shelf
  SimOptions options;
  std::vector<double> rpms, depths_m;
  std::uint64_t seed = 0;

  WaterColumn water() const;  // the cast with the internal wave
  std::string describe() const;
};

SurveyMission makeSurveyMission(std::uint64_t seed, const SurveyRanges& ranges = {});

// Realistic drop-outs: bursts where the DVL loses bottom/water track (speed),
// the CTD and the attitude sensor skip samples. About `fraction` of each
// affected channel's rows become NaN.
void applyDropouts(MissionLog& log, std::uint64_t seed, double fraction = 0.03);

}  // namespace auv::sim
