#include "plot/plot_trace.h"

#include <algorithm>

namespace auv::ui {

PlotTrace preparePlotTrace(const MissionLog& log, const char* channel) {
  PlotTrace out;
  if (!channel || !log.has(channel)) return out;
  out.channel = channel;
  TimeSeries ts = log.series(channel);
  out.t_min.resize(ts.t.size());
  std::transform(ts.t.begin(), ts.t.end(), out.t_min.begin(), [](double t) { return t / 60.0; });
  out.v = std::move(ts.v);
  out.pyramid = MinMaxPyramid(out.v);
  return out;
}

}  // namespace auv::ui
