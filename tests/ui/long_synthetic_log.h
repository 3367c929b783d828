#pragma once
// A very long survey log made up in memory in well under a second: the
// 90 min survey of synthetic_log.h repeated for `hours` at 1 Hz, each repeat
// a little different (roll and pitch drift slowly over the mission), with
// one sample of pitch `spike_deg` at row `spike_row` (a bad sample a plot
// must still show at any zoom). 1100 h is the log after which the window
// froze in issue 14: 3 960 000 rows, 5 channels.
#include <cmath>
#include <cstddef>

#include "synthetic_log.h"

namespace auv::testing {

inline MissionLog syntheticLongSurvey(double hours, std::size_t spike_row, double spike_deg = 40.0) {
  const MissionLog cycle = syntheticSurvey();
  const std::size_t period = cycle.rowCount();
  const std::size_t n = static_cast<std::size_t>(hours * 3600.0);
  MissionLog log;
  log.setMetadata("vehicle", "hugin1000");
  log.setMetadata("mission", "synthetic long survey for the big-log tests");
  log.setMetadata("start", "2026-05-14T08:12:00Z");
  log.time.resize(n);
  const char* names[] = {"depth", "depth_cmd", "pitch", "pitch_cmd", "roll"};
  for (const char* name : names) {
    const LogChannel& from = cycle.channel(name);
    LogChannel& to = log.addChannel(name, from.unit);
    for (std::size_t i = 0; i < n; ++i) to.values[i] = from.values[i % period];
  }
  LogChannel& pitch = *log.find("pitch");
  LogChannel& roll = *log.find("roll");
  for (std::size_t i = 0; i < n; ++i) {
    log.time[i] = static_cast<double>(i);
    const double c = static_cast<double>(i / period);
    pitch.values[i] += 0.2 * std::sin(c / 40.0);
    roll.values[i] += 0.5 * std::sin(c / 90.0);
  }
  if (spike_row < n) pitch.values[spike_row] = spike_deg;
  return log;
}

}  // namespace auv::testing
