#include "plot/nice_axis.h"

#include <algorithm>
#include <cmath>

namespace auv::ui {

NiceAxis niceAxis(double lo, double hi, int target_ticks) {
  NiceAxis a;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return a;
  if (hi < lo) std::swap(lo, hi);
  if (hi - lo < 1e-12) {
    const double pad = std::max(std::abs(lo) * 0.05, 0.5);
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / std::max(target_ticks, 2);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  a.step = (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0) * mag;
  a.min = std::floor(lo / a.step + 1e-9) * a.step;
  a.max = std::ceil(hi / a.step - 1e-9) * a.step;
  a.ticks = static_cast<int>(std::lround((a.max - a.min) / a.step)) + 1;
  return a;
}

}  // namespace auv::ui
