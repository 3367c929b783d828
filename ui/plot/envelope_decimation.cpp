#include "plot/envelope_decimation.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace auv::ui {
namespace {

std::size_t lowerIndex(std::span<const double> t, double x) {
  return static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), x) - t.begin());
}

// The nearest finite sample before index `lo` / from index `hi` on.
std::optional<PlotPoint> before(std::span<const double> t, std::span<const double> v, std::size_t lo) {
  for (std::size_t i = lo; i-- > 0;)
    if (std::isfinite(v[i])) return PlotPoint{t[i], v[i]};
  return std::nullopt;
}
std::optional<PlotPoint> from(std::span<const double> t, std::span<const double> v, std::size_t hi) {
  for (std::size_t i = hi; i < v.size(); ++i)
    if (std::isfinite(v[i])) return PlotPoint{t[i], v[i]};
  return std::nullopt;
}

}  // namespace

Envelope decimateEnvelope(std::span<const double> t, std::span<const double> v, const MinMaxPyramid& pyramid,
                          double x0, double x1, std::size_t buckets, double dense_from) {
  Envelope out;
  const std::size_t n = std::min({t.size(), v.size(), pyramid.size()});
  if (n == 0 || !(x1 > x0) || buckets == 0) return out;
  t = t.first(n);
  v = v.first(n);
  const std::size_t lo = lowerIndex(t, x0);
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x1) - t.begin());
  const auto left = before(t, v, lo), right = from(t, v, hi);
  out.dense = static_cast<double>(hi - lo) > dense_from * static_cast<double>(buckets);
  auto pushAll = [&](const PlotPoint& p) {
    out.line.push_back(p);
    if (out.dense) {
      out.lower.push_back(p);
      out.upper.push_back(p);
    }
  };
  if (left) pushAll(*left);
  if (hi - lo <= 2 * buckets) {
    for (std::size_t i = lo; i < hi; ++i)
      if (std::isfinite(v[i])) out.line.push_back({t[i], v[i]});
  } else {
    out.line.reserve(2 * buckets + 2);
    const double width = (x1 - x0) / static_cast<double>(buckets);
    std::size_t i = lo;
    for (std::size_t b = 0; b < buckets && i < hi; ++b) {
      // The last column takes everything up to x1.
      std::size_t end = hi;
      if (b + 1 < buckets) {
        const double edge = x0 + width * static_cast<double>(b + 1);
        end = static_cast<std::size_t>(std::lower_bound(t.begin() + static_cast<std::ptrdiff_t>(i),
                                                        t.begin() + static_cast<std::ptrdiff_t>(hi), edge) - t.begin());
      }
      const MinMaxPyramid::Summary s = pyramid.query(v, i, end);
      i = end;
      if (s.count == 0) continue;  // empty column: the line bridges it
      if (out.dense) {
        out.lower.push_back({t[s.imin], v[s.imin]});
        out.upper.push_back({t[s.imax], v[s.imax]});
        out.line.push_back({(t[s.first] + t[s.last]) / 2.0, s.sum / static_cast<double>(s.count)});
      } else if (s.imin == s.imax) {
        out.line.push_back({t[s.imin], v[s.imin]});
      } else {
        const std::size_t a = std::min(s.imin, s.imax), z = std::max(s.imin, s.imax);
        out.line.push_back({t[a], v[a]});
        out.line.push_back({t[z], v[z]});
      }
    }
  }
  if (right) pushAll(*right);
  return out;
}

}  // namespace auv::ui
