#include "analysis/classic_thesis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "analysis/series_tools.h"

namespace auv::analysis::classic {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// MATLAB round(): half away from zero; result is a 1-based index.
std::size_t matlabRound(double x) { return static_cast<std::size_t>(std::round(x)); }

// Mean of v(first:last) (1-based, inclusive) after dropping NaNs, where
// `nan_first` says whether NaNs are removed before (D.1) or after (D.2/D.3)
// taking the window.
ClassicValue windowMean(const std::vector<double>& v, std::size_t original_length, bool nan_first) {
  ClassicValue r;
  const std::size_t first = matlabRound(0.4 * static_cast<double>(original_length));
  std::size_t last = matlabRound(0.6 * static_cast<double>(original_length));
  std::vector<double> a;
  if (nan_first) {
    for (double x : v)
      if (!std::isnan(x)) a.push_back(x);
  } else {
    a = v;
  }
  if (last > a.size()) {
    last = a.size();
    r.index_clamped = true;
  }
  double sum = 0.0;
  for (std::size_t i = first == 0 ? 1 : first; i <= last; ++i) {
    const double x = a[i - 1];
    if (std::isnan(x)) continue;
    sum += x;
    ++r.samples;
  }
  r.value = r.samples ? sum / static_cast<double>(r.samples) : kNaN;
  return r;
}

// `source` read at the (increasing) times `at` in one forward pass.
std::vector<double> readAt(const TimeSeries& source, const std::vector<double>& at, bool hold, double max_gap_s) {
  SeriesCursor c(source, hold, max_gap_s);
  std::vector<double> out(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) out[i] = c.at(at[i]);
  return out;
}

}  // namespace

ClassicValue depthComparison(std::span<const double> cmd, std::span<const double> meas) {
  const std::size_t n = std::min(cmd.size(), meas.size());
  std::vector<double> check(n, 0.0);
  std::size_t i = 2;  // 1-based, as in the MATLAB code
  while (i <= n) {
    const double c = cmd[i - 1], p = cmd[i - 2];
    if (c == p) {
      check[i - 1] = c - meas[i - 1];
      i += 1;
    } else {
      const double step = std::abs(c - p);
      check[i - 1] = kNaN;
      if (step < 30) i += 300;
      else if (step < 50) i += 400;
      else if (step < 100) i += 500;
      else i += 600;  // also NaN steps: every comparison with NaN is false
    }
  }
  return windowMean(check, n, true);
}

ClassicValue pitchComparison(std::span<const double> meas, std::span<const double> cmd) {
  const std::size_t n = std::min(meas.size(), cmd.size());
  std::vector<double> check(n, 0.0);
  for (std::size_t i = 3; i <= n; ++i) check[i - 1] = meas[i - 1] - cmd[i - 1];
  return windowMean(check, meas.size(), false);
}

ClassicValue pitchAtStableDepth(std::span<const double> pitch, std::span<const double> depth) {
  const std::size_t n = std::min(pitch.size(), depth.size());
  std::vector<double> check(n, 0.0);
  for (std::size_t i = 3; i <= n; ++i)
    check[i - 1] = (depth[i - 1] == depth[i - 2] && depth[i - 2] == depth[i - 3]) ? pitch[i - 1] : kNaN;
  return windowMean(check, pitch.size(), false);
}

ClassicValue rollAtCruise(std::span<const double> roll, std::span<const double> rpm, std::span<const double> speed,
                          double rpm_exact, double speed_center, double half) {
  ClassicValue r;
  const std::size_t n = std::min({roll.size(), rpm.size(), speed.size()});
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (rpm[i] == rpm_exact && speed[i] > speed_center - half && speed[i] < speed_center + half && !std::isnan(roll[i])) {
      sum += roll[i];
      ++r.samples;
    }
  }
  r.value = r.samples ? sum / static_cast<double>(r.samples) : kNaN;
  return r;
}

ClassicReport classicAnalysis(const MissionLog& log, double rpm_exact, double speed_center) {
  ClassicReport rep;
  constexpr double kHoldGap = std::numeric_limits<double>::infinity(), kLinearGap = 60.0;
  if (log.has("depth") && log.has("depth_cmd")) {
    const TimeSeries d = log.series("depth");
    rep.depth_error_m = depthComparison(readAt(log.series("depth_cmd"), d.t, true, kHoldGap), d.v);
    rep.has_depth = true;
  }
  if (log.has("pitch")) {
    const TimeSeries p = log.series("pitch");
    if (log.has("pitch_cmd")) {
      rep.pitch_error_deg = pitchComparison(p.v, readAt(log.series("pitch_cmd"), p.t, true, kHoldGap));
      rep.has_pitch = true;
    }
    if (log.has("depth")) {
      rep.pitch_at_stable_depth_deg = pitchAtStableDepth(p.v, readAt(log.series("depth"), p.t, false, kLinearGap));
      rep.has_pitch_depth = true;
    }
  }
  if (log.has("roll") && log.has("prop_rpm") && log.has("speed")) {
    const TimeSeries r = log.series("roll");
    rep.roll_error_deg = rollAtCruise(r.v, readAt(log.series("prop_rpm"), r.t, false, kLinearGap),
                                      readAt(log.series("speed"), r.t, false, kLinearGap), rpm_exact, speed_center);
    rep.has_roll = true;
  }
  return rep;
}

}  // namespace auv::analysis::classic
