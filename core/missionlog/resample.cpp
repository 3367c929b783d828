#include "missionlog/resample.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace auv {

std::vector<double> resample(const TimeSeries& s, std::span<const double> at,
                             const ResampleOptions& o) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> out(at.size(), nan);
  const std::size_t n = std::min(s.t.size(), s.v.size());
  if (n == 0) return out;
  const double* t = s.t.data();
  for (std::size_t k = 0; k < at.size(); ++k) {
    const double x = at[k];
    if (!(x >= t[0] && x <= t[n - 1])) {  // also rejects NaN targets
      if (o.method == Interpolation::kHold && x > t[n - 1] && x - t[n - 1] <= o.max_gap_s)
        out[k] = s.v[n - 1];
      continue;
    }
    // First sample strictly after x; x lies in [t[j-1], t[j]).
    const std::size_t j = static_cast<std::size_t>(std::upper_bound(t, t + n, x) - t);
    const std::size_t i = j - 1;
    if (t[i] == x) {
      out[k] = s.v[i];
    } else if (o.method == Interpolation::kHold) {
      if (x - t[i] <= o.max_gap_s) out[k] = s.v[i];
    } else if (t[j] - t[i] <= o.max_gap_s) {
      const double w = (x - t[i]) / (t[j] - t[i]);
      out[k] = s.v[i] + w * (s.v[j] - s.v[i]);
    }
  }
  return out;
}

std::vector<double> uniformGrid(double t0, double t1, double dt) {
  if (!(dt > 0.0) || !std::isfinite(t0) || !std::isfinite(t1) || !std::isfinite(dt))
    throw std::invalid_argument("uniformGrid: need finite t0, t1 and dt > 0");
  std::vector<double> g;
  if (t1 < t0) return g;
  const double steps = std::floor((t1 - t0) / dt + 1e-9);
  if (steps > 1e9) throw std::invalid_argument("uniformGrid: more than 1e9 points");
  const auto n = static_cast<std::size_t>(steps) + 1;
  g.reserve(n);
  for (std::size_t k = 0; k < n; ++k) g.push_back(t0 + static_cast<double>(k) * dt);
  return g;
}

TimeSeries alignTo(const MissionLog& log, std::string_view name, std::string_view onto,
                   const ResampleOptions& options) {
  TimeSeries out;
  out.t = log.validTimes(onto);
  out.v = resample(log.series(name), out.t, options);
  return out;
}

TimeSeries resampleUniform(const MissionLog& log, std::string_view name, double dt,
                           const ResampleOptions& options) {
  const TimeSeries s = log.series(name);
  TimeSeries out;
  if (s.empty()) return out;
  out.t = uniformGrid(s.t.front(), s.t.back(), dt);
  out.v = resample(s, out.t, options);
  return out;
}

}  // namespace auv
