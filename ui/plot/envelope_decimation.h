#pragma once
// What to draw for one series over a visible time range, bounded by the plot
// width whatever the log's length (issue 14: after a 1100 h log the plots
// were a solid block). Sparse (at most `dense_from` samples per pixel
// column): the samples, or each column's min and max in time order, as one
// line, exactly as decimateMinMax. Dense: an envelope, each column's min
// (lower) and max (upper) at the times they occurred, drawn as a light band,
// with the column's mean as the line through it, so the level and its
// spread stay readable where a min/max zig-zag would fill the band solid.
// Every column's min and max are in the output either way, so one bad
// sample among millions shows. Pure C++ (no Qt).
#include <cstddef>
#include <span>
#include <vector>

#include "plot/min_max_decimation.h"
#include "plot/min_max_pyramid.h"

namespace auv::ui {

struct Envelope {
  bool dense = false;
  std::vector<PlotPoint> line;   // sparse: the min/max line; dense: the column means
  std::vector<PlotPoint> lower;  // dense only: each column's min
  std::vector<PlotPoint> upper;  // dense only: each column's max
};

// Columns with more samples than this on average draw as an envelope.
inline constexpr double kDenseSamplesPerColumn = 16.0;

// `pyramid` was built from `v`; t strictly increasing, NaN = not sampled.
// Each of the three lines holds at most 2 x `buckets` + 2 points (the
// nearest sample outside the range on each side is kept, so lines run to the
// plot edges).
Envelope decimateEnvelope(std::span<const double> t, std::span<const double> v, const MinMaxPyramid& pyramid,
                          double x0, double x1, std::size_t buckets,
                          double dense_from = kDenseSamplesPerColumn);

}  // namespace auv::ui
