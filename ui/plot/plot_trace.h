#pragma once
// One channel of a log ready for plotting: its sampled times in minutes, its
// values and the min/max pyramid that makes decimating any visible range
// cheap. Built in a worker thread for every plotted channel when a log is
// shown (4 million samples take ~0.1 s), then only read. Pure C++ (no Qt).
#include <vector>

#include "missionlog/mission_log.h"
#include "plot/min_max_pyramid.h"

namespace auv::ui {

struct PlotTrace {
  const char* channel = nullptr;  // nullptr: not plotted (not in the log)
  std::vector<double> t_min;      // minutes since the log's time zero
  std::vector<double> v;
  MinMaxPyramid pyramid;          // over v
};

// The channel's valid samples; an empty trace when `channel` is null or not
// in the log.
PlotTrace preparePlotTrace(const MissionLog& log, const char* channel);

}  // namespace auv::ui
