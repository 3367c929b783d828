#pragma once
// Builds MissionLog objects in tests: a row time base and channels filled
// from functions of time (NaN = not sampled at that row).
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "missionlog/mission_log.h"

namespace auv::analysis::test {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline MissionLog makeLog(double t0, double t1, double dt) {
  MissionLog log;
  const auto n = static_cast<std::size_t>(std::floor((t1 - t0) / dt + 1e-9)) + 1;
  log.time.reserve(n);
  for (std::size_t i = 0; i < n; ++i) log.time.push_back(t0 + static_cast<double>(i) * dt);
  return log;
}

// f(row index, time) -> value or NaN.
inline void fill(MissionLog& log, const std::string& name, const std::string& unit,
                 const std::function<double(std::size_t, double)>& f) {
  LogChannel& c = log.addChannel(name, unit);
  for (std::size_t i = 0; i < log.time.size(); ++i) c.values[i] = f(i, log.time[i]);
}

}  // namespace auv::analysis::test
