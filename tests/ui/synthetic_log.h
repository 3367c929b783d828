#pragma once
// A survey-like mission log made up here, for the screenshot goldens: depth
// steps with a rate-limited response, the pitch the autopilot would command
// for them, and a slowly drifting roll. It depends on nothing but this file
// (not on the simulator, which evolves), so the plots stay the same.
#include <algorithm>
#include <cmath>
#include <string>

#include "missionlog/interchange_csv.h"
#include "missionlog/mission_log.h"

namespace auv::testing {

inline MissionLog syntheticSurvey() {
  MissionLog log;
  log.setMetadata("vehicle", "hugin1000");
  log.setMetadata("mission", "synthetic survey for the GUI tests");
  log.setMetadata("start", "2026-05-14T08:12:00Z");
  const int n = 90 * 60;  // 90 min at 1 Hz
  log.time.resize(n);
  LogChannel& depth = log.addChannel("depth", "m");
  LogChannel& depth_cmd = log.addChannel("depth_cmd", "m");
  LogChannel& pitch = log.addChannel("pitch", "deg");
  LogChannel& pitch_cmd = log.addChannel("pitch_cmd", "deg");
  LogChannel& roll = log.addChannel("roll", "deg");
  double z = 2.0, p = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = i;
    const double cmd = t < 300 ? 20 : t < 2100 ? 50 : t < 3900 ? 100 : t < 5100 ? 50 : 5;
    const double err = cmd - z;
    const double pc = std::clamp(-err * 1.5, -15.0, 15.0);  // nose down to go deeper
    p += (pc - p) * 0.15;
    z += std::clamp(err * 0.05, -0.6, 0.6);
    log.time[static_cast<std::size_t>(i)] = t;
    depth.values[static_cast<std::size_t>(i)] = z + 0.05 * std::sin(0.9 * t);
    depth_cmd.values[static_cast<std::size_t>(i)] = cmd;
    pitch.values[static_cast<std::size_t>(i)] = p - 1.6 + 0.3 * std::sin(0.37 * t) + 0.2 * std::sin(1.3 * t);
    pitch_cmd.values[static_cast<std::size_t>(i)] = pc;
    roll.values[static_cast<std::size_t>(i)] = 2.4 + 0.8 * std::sin(t / 600.0) + 0.04 * std::sin(2.1 * t) + 0.03 * std::sin(0.71 * t);
  }
  return log;
}

inline std::size_t writeSyntheticSurvey(const std::string& path) {
  const MissionLog log = syntheticSurvey();
  writeInterchangeCsv(log, path);
  return log.rowCount();
}

}  // namespace auv::testing
