#pragma once
// Small single-pass tools on one channel's own time base: a local rate
// estimate and a forward-only cursor that reads another channel at increasing
// times without per-lookup searches or allocation.
#include <cstddef>
#include <span>
#include <vector>

#include "missionlog/mission_log.h"

namespace auv::analysis {

// Rate of change at every sample: (mean of the samples in (t, t + W/2]
// minus mean in [t - W/2, t)) over the difference of their mean times. A
// boxcar derivative: insensitive to sample-to-sample noise, O(n) with running
// sums, NaN where either half is empty or the halves span a gap longer than
// `max_gap_s`. The half width is widened to at least `min_side_samples`
// median sample intervals so sparse channels still get a rate.
std::vector<double> localRate(const TimeSeries& s, double window_s, double max_gap_s,
                              double min_side_samples = 2.0);

// Median sample interval (0 for fewer than two samples).
double medianInterval(std::span<const double> t);

// Reads a TimeSeries at non-decreasing query times. `hold` returns the last
// sample at or before t (commands); otherwise linear interpolation between
// the neighbours. NaN outside the record or across a gap > max_gap_s.
class SeriesCursor {
 public:
  SeriesCursor(const TimeSeries& s, bool hold, double max_gap_s);
  double at(double t);
  bool empty() const { return s_->empty(); }

 private:
  const TimeSeries* s_;
  bool hold_;
  double max_gap_s_;
  std::size_t j_ = 0;  // first sample with time > last query
};

struct TimeWindow {
  double start_s = 0.0;
  double end_s = 0.0;
  double duration() const { return end_s - start_s; }
};

// Sorted, non-overlapping union of the windows.
std::vector<TimeWindow> mergeWindows(std::vector<TimeWindow> w);
// `base` minus `cut` (both sorted and non-overlapping).
std::vector<TimeWindow> subtractWindows(const std::vector<TimeWindow>& base,
                                        const std::vector<TimeWindow>& cut);

}  // namespace auv::analysis
