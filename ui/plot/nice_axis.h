#pragma once
// Round axis limits for a value range: ticks at 1, 2 or 5 times a power of
// ten, limits on ticks. Done here rather than with QValueAxis::applyNiceNumbers,
// which on some ranges made Qt Charts 6.4 bounce between the axis and the
// chart domain without end (observed with the comet recording). Pure C++.

namespace auv::ui {

struct NiceAxis {
  double min = 0.0;
  double max = 1.0;
  double step = 0.25;
  int ticks = 5;  // including both ends
};

// `lo` <= `hi`, finite; about `target_ticks` intervals (at least 2).
NiceAxis niceAxis(double lo, double hi, int target_ticks = 4);

}  // namespace auv::ui
