#pragma once
// Walking a log's samples inside a set of time windows (segments), shared by
// the analysis's statistics and the water at depth.
#include <cmath>
#include <cstddef>
#include <vector>

#include "analysis/segments.h"
#include "missionlog/mission_log.h"

namespace auv::analysis {

// At least `min` non-NaN samples in channel `name`.
inline bool hasSamples(const MissionLog& log, const char* name, std::size_t min = 1) {
  const LogChannel* c = log.find(name);
  if (!c) return false;
  std::size_t n = 0;
  for (double v : c->values)
    if (!std::isnan(v) && ++n >= min) return true;
  return false;
}

// f(window index, time, value) for every sample of s inside the windows.
template <class F>
void forEachInWindows(const TimeSeries& s, const std::vector<Segment>& win, F&& f) {
  std::size_t w = 0;
  for (std::size_t i = 0; i < s.size() && w < win.size(); ++i) {
    const double t = s.t[i];
    while (w < win.size() && t > win[w].end_s) ++w;
    if (w == win.size()) break;
    if (t >= win[w].start_s) f(w, t, s.v[i]);
  }
}

}  // namespace auv::analysis
