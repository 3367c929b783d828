#pragma once
// Min/max-per-pixel decimation for line plots of long logs: a 24 h 10 Hz log
// has ~1e6 samples but the chart is ~1000 px wide. Per pixel column we keep
// the smallest and the largest sample (in time order), so every spike and
// every envelope edge a full render would show is still drawn, while the
// series handed to Qt Charts stays at <= 2 points per pixel (measured: 0.15 %
// of pixels differ from the full render, see qt-headless-notes.md).
// Pure C++ (no Qt) so it is tested and benchmarked without widgets.
#include <cstddef>
#include <span>
#include <vector>

namespace auv::ui {

struct PlotPoint {
  double x = 0.0;
  double y = 0.0;
};

// Samples (t[i], v[i]) with t strictly increasing; NaN values are skipped.
// Returns the samples to draw for the visible range [x0, x1] split into
// `buckets` equal columns: all samples if there are at most 2 per bucket,
// else each non-empty bucket's min and max in time order. The nearest sample
// outside the range on each side is kept too, so the line runs to the plot
// edges instead of stopping at the last visible sample.
std::vector<PlotPoint> decimateMinMax(std::span<const double> t, std::span<const double> v, double x0, double x1,
                                      std::size_t buckets);

}  // namespace auv::ui
