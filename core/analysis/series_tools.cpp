#include "analysis/series_tools.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace auv::analysis {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

double medianInterval(std::span<const double> t) {
  if (t.size() < 2) return 0.0;
  // Subsample long records: the median of 4096 evenly spread intervals is as
  // good and keeps this O(1) in memory.
  const std::size_t n = t.size() - 1;
  const std::size_t step = std::max<std::size_t>(1, n / 4096);
  std::vector<double> d;
  d.reserve(n / step + 1);
  for (std::size_t i = 0; i < n; i += step) d.push_back(t[i + 1] - t[i]);
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

std::vector<double> localRate(const TimeSeries& s, double window_s, double max_gap_s,
                              double min_side_samples) {
  const std::size_t n = s.size();
  std::vector<double> rate(n, kNaN);
  if (n < 2) return rate;
  const double half = std::max(0.5 * window_s, min_side_samples * medianInterval(s.t));
  const double* t = s.t.data();
  const double* v = s.v.data();
  // Times relative to the first sample keep the running sums small; values
  // relative to the first value likewise.
  const double t0 = t[0], v0 = v[0];
  // Left half [t - half, t): indices [a, i). Right half (t, t + half]: (i, b].
  std::size_t a = 0, b = 0;
  double lt = 0, lv = 0, rt = 0, rv = 0;
  std::size_t ln = 0, rn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Left: add sample i-1, drop samples older than t - half.
    if (i > 0) {
      lt += t[i - 1] - t0;
      lv += v[i - 1] - v0;
      ++ln;
    }
    while (a < i && t[a] < t[i] - half) {
      lt -= t[a] - t0;
      lv -= v[a] - v0;
      --ln;
      ++a;
    }
    // Right: drop sample i (now the centre), add samples up to t + half.
    if (b <= i) {
      b = i;
      rt = rv = 0;
      rn = 0;
    } else {
      rt -= t[i] - t0;
      rv -= v[i] - v0;
      --rn;
    }
    while (b + 1 < n && t[b + 1] <= t[i] + half) {
      ++b;
      rt += t[b] - t0;
      rv += v[b] - v0;
      ++rn;
    }
    if (ln == 0 || rn == 0) continue;
    // A gap inside the window makes the two halves unrelated.
    if ((i > 0 && t[i] - t[i - 1] > max_gap_s) || (i + 1 < n && t[i + 1] - t[i] > max_gap_s)) continue;
    const double dl = lt / static_cast<double>(ln), dr = rt / static_cast<double>(rn);
    if (dr - dl <= 0) continue;
    rate[i] = (rv / static_cast<double>(rn) - lv / static_cast<double>(ln)) / (dr - dl);
  }
  return rate;
}

SeriesCursor::SeriesCursor(const TimeSeries& s, bool hold, double max_gap_s)
    : s_(&s), hold_(hold), max_gap_s_(max_gap_s) {}

double SeriesCursor::at(double t) {
  const std::size_t n = s_->size();
  if (n == 0 || !(t >= s_->t[0])) return kNaN;
  while (j_ < n && s_->t[j_] <= t) ++j_;
  const std::size_t i = j_ - 1;  // last sample at or before t
  const double ti = s_->t[i];
  if (ti == t) return s_->v[i];
  if (hold_) return t - ti <= max_gap_s_ ? s_->v[i] : kNaN;
  if (j_ >= n) return kNaN;
  const double tj = s_->t[j_];
  if (tj - ti > max_gap_s_) return kNaN;
  return s_->v[i] + (t - ti) / (tj - ti) * (s_->v[j_] - s_->v[i]);
}

std::vector<TimeWindow> mergeWindows(std::vector<TimeWindow> w) {
  std::sort(w.begin(), w.end(), [](const TimeWindow& x, const TimeWindow& y) { return x.start_s < y.start_s; });
  std::vector<TimeWindow> out;
  for (const TimeWindow& x : w) {
    if (!(x.end_s > x.start_s)) continue;
    if (!out.empty() && x.start_s <= out.back().end_s) {
      out.back().end_s = std::max(out.back().end_s, x.end_s);
    } else {
      out.push_back(x);
    }
  }
  return out;
}

std::vector<TimeWindow> subtractWindows(const std::vector<TimeWindow>& base, const std::vector<TimeWindow>& cut) {
  std::vector<TimeWindow> out;
  std::size_t k = 0;
  for (const TimeWindow& b : base) {
    double start = b.start_s;
    while (k < cut.size() && cut[k].end_s <= start) ++k;
    std::size_t j = k;
    while (j < cut.size() && cut[j].start_s < b.end_s) {
      if (cut[j].start_s > start) out.push_back({start, cut[j].start_s});
      start = std::max(start, cut[j].end_s);
      ++j;
    }
    if (start < b.end_s) out.push_back({start, b.end_s});
  }
  return out;
}

}  // namespace auv::analysis
