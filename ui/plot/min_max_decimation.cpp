#include "plot/min_max_decimation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace auv::ui {

std::vector<PlotPoint> decimateMinMax(std::span<const double> t, std::span<const double> v, double x0, double x1,
                                      std::size_t buckets) {
  std::vector<PlotPoint> out;
  const std::size_t n = std::min(t.size(), v.size());
  if (n == 0 || !(x1 > x0) || buckets == 0) return out;
  // Visible index range [lo, hi) by binary search: t is sorted.
  const auto first = t.begin();
  std::size_t lo = static_cast<std::size_t>(std::lower_bound(first, first + static_cast<std::ptrdiff_t>(n), x0) - first);
  std::size_t hi = static_cast<std::size_t>(std::upper_bound(first, first + static_cast<std::ptrdiff_t>(n), x1) - first);
  // The neighbour just outside on each side (skipping unsampled rows).
  auto pushValid = [&](std::size_t i) {
    if (std::isfinite(v[i])) out.push_back({t[i], v[i]});
  };
  for (std::size_t i = lo; i-- > 0;) {
    if (std::isfinite(v[i])) {
      out.push_back({t[i], v[i]});
      break;
    }
  }
  if (hi - lo <= 2 * buckets) {
    for (std::size_t i = lo; i < hi; ++i) pushValid(i);
  } else {
    out.reserve(2 * buckets + 2);
    const double width = (x1 - x0) / static_cast<double>(buckets);
    const auto tb = t.begin();
    std::size_t i = lo;
    for (std::size_t b = 0; b < buckets && i < hi; ++b) {
      // This column's samples by binary search (the last column takes
      // everything up to x1), then a branch-light scan of its values.
      std::size_t end = hi;
      if (b + 1 < buckets) {
        const double edge = x0 + width * static_cast<double>(b + 1);
        end = static_cast<std::size_t>(std::lower_bound(tb + static_cast<std::ptrdiff_t>(i),
                                                        tb + static_cast<std::ptrdiff_t>(hi), edge) - tb);
      }
      // NaN (not sampled) fails both comparisons, so it is skipped for free.
      double vmin = std::numeric_limits<double>::infinity(), vmax = -vmin;
      std::size_t imin = end, imax = end;
      for (std::size_t k = i; k < end; ++k) {
        const double x = v[k];
        if (x < vmin) {
          vmin = x;
          imin = k;
        }
        if (x > vmax) {
          vmax = x;
          imax = k;
        }
      }
      i = end;
      if (imin == end) continue;  // empty column: the line bridges it
      if (imin == imax) {
        out.push_back({t[imin], v[imin]});
      } else {
        const std::size_t first_i = std::min(imin, imax), last_i = std::max(imin, imax);
        out.push_back({t[first_i], v[first_i]});
        out.push_back({t[last_i], v[last_i]});
      }
    }
  }
  for (std::size_t i = hi; i < n; ++i) {
    if (std::isfinite(v[i])) {
      out.push_back({t[i], v[i]});
      break;
    }
  }
  return out;
}

}  // namespace auv::ui
