#include "analysis/averaged_legs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "analysis/series_tools.h"

namespace auv::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kSmooth_s = 30.0;       // boxcar that hides sensor noise, well below a cycle
constexpr double kHysteresis = 0.3;      // of the smoothed signal's sd: noise near the mean is no crossing
constexpr double kPhaseErrorFrac = 0.15;  // cycle boundaries found to ~this of the sd per cycle

// Samples of s inside [a, b], smoothed with a centred boxcar of width_s.
TimeSeries smoothedIn(const TimeSeries& s, double a, double b, double width_s = kSmooth_s) {
  const auto lo = std::lower_bound(s.t.begin(), s.t.end(), a) - s.t.begin();
  const auto hi = std::upper_bound(s.t.begin(), s.t.end(), b) - s.t.begin();
  TimeSeries out;
  double sum = 0.0;
  std::ptrdiff_t l = lo, r = lo;  // running window [l, r)
  for (std::ptrdiff_t i = lo; i < hi; ++i) {
    while (r < hi && s.t[r] <= s.t[i] + 0.5 * width_s) sum += s.v[r++];
    while (s.t[l] < s.t[i] - 0.5 * width_s) sum -= s.v[l++];
    out.t.push_back(s.t[i]);
    out.v.push_back(sum / static_cast<double>(r - l));
  }
  return out;
}

struct MeanSd {
  double mean = 0.0, sd = 0.0;
};

// Mean and sample standard deviation (0 with fewer than two values).
MeanSd meanSdOf(const std::vector<double>& v) {
  MeanSd r;
  if (v.empty()) return r;
  for (double x : v) r.mean += x;
  r.mean /= static_cast<double>(v.size());
  if (v.size() < 2) return r;
  double m2 = 0.0;
  for (double x : v) m2 += (x - r.mean) * (x - r.mean);
  r.sd = std::sqrt(m2 / static_cast<double>(v.size() - 1));
  return r;
}

double sdOf(const std::vector<double>& v) { return meanSdOf(v).sd; }

// Upward crossings of the signal's mean with hysteresis; cycles shorter than
// min_period_s are merged into the next.
std::vector<double> upCrossings(const TimeSeries& x, double min_period_s) {
  std::vector<double> out;
  if (x.size() < 4) return out;
  const MeanSd ms = meanSdOf(x.v);
  const double m = ms.mean, h = kHysteresis * ms.sd;
  if (!(h > 0.0)) return out;
  int state = 0;  // -1 below m - h, +1 above m + h
  double last_cross = kNaN;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (x.v[i - 1] <= m && x.v[i] > m)
      last_cross = x.t[i - 1] + (m - x.v[i - 1]) / (x.v[i] - x.v[i - 1]) * (x.t[i] - x.t[i - 1]);
    if (x.v[i] < m - h) state = -1;
    if (x.v[i] > m + h) {
      if (state == -1 && std::isfinite(last_cross) && (out.empty() || last_cross - out.back() >= min_period_s))
        out.push_back(last_cross);
      state = 1;
    }
  }
  return out;
}

double overlap(const std::vector<Segment>& w, double a, double b) {
  double s = 0.0;
  for (const Segment& x : w) s += std::max(0.0, std::min(b, x.end_s) - std::max(a, x.start_s));
  return s;
}

// The first time at or after t0 that the depth comes within `arrive_m` of
// the command, and whether it then stays inside `band_m` until t1.
std::optional<double> arrivedAndHeld(const TimeSeries& depth, const TimeSeries& cmd, double t0, double t1,
                                     double arrive_m, double band_m) {
  SeriesCursor c(cmd, true, std::numeric_limits<double>::infinity());
  std::optional<double> arrived;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    const double t = depth.t[i];
    if (t < t0) continue;
    if (t > t1) break;
    const double e = std::abs(depth.v[i] - c.at(t));
    if (!arrived && e <= arrive_m) arrived = t;
    if (arrived && !(e <= band_m)) return std::nullopt;
  }
  return arrived;
}

// The longest run in [a, b] where the pitch, smoothed over 6 s, stays
// within tol_deg of its median there: the pitch-limited middle of a depth
// change (the autopilot's pitch limit), or a steady sink.
std::optional<TimeWindow> pitchPlateau(const TimeSeries& pitch, double a, double b, double tol_deg) {
  constexpr double kPlateauSmooth_s = 6.0;
  const TimeSeries sm = smoothedIn(pitch, a, b, kPlateauSmooth_s);
  if (sm.size() < 3) return std::nullopt;
  std::vector<double> sorted = sm.v;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double med = sorted[sorted.size() / 2];
  std::optional<TimeWindow> best;
  std::size_t i = 0;
  while (i < sm.size()) {
    if (!(std::abs(sm.v[i] - med) <= tol_deg)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < sm.size() && std::abs(sm.v[j + 1] - med) <= tol_deg) ++j;
    if (!best || sm.t[j] - sm.t[i] > best->duration()) best = TimeWindow{sm.t[i], sm.t[j]};
    i = j + 1;
  }
  return best;
}

}  // namespace

std::vector<Segment> averagedLegs(const MissionLog& log, const TimeSeries& depth,
                                  const std::vector<TimeWindow>& command_cuts, const std::vector<Segment>& steady,
                                  const SegmentOptions& o) {
  std::vector<Segment> out;
  if (depth.size() < 2 || !log.has("depth_cmd") || !log.has("pitch")) return out;
  const TimeSeries cmd = log.series("depth_cmd");
  const TimeSeries pitch = log.series("pitch");
  if (cmd.empty() || pitch.size() < 4) return out;
  // A data gap ends a leg: no cycle is counted across it.
  std::vector<TimeWindow> cuts = command_cuts;
  for (std::size_t i = 1; i < depth.size(); ++i)
    if (depth.t[i] - depth.t[i - 1] > o.max_gap_s) cuts.push_back({depth.t[i - 1], depth.t[i] + o.settle_s});
  const std::vector<TimeWindow> legs = subtractWindows({{depth.t.front(), depth.t.back()}}, mergeWindows(std::move(cuts)));
  for (const TimeWindow& leg : legs) {
    if (leg.duration() < o.average_min_s) continue;
    const std::optional<double> arrived =
        arrivedAndHeld(depth, cmd, leg.start_s, leg.end_s, o.average_arrive_m, o.average_depth_band_m);
    if (!arrived) continue;
    const double a = *arrived + o.settle_s;
    if (leg.end_s - a < o.average_min_s) continue;
    const TimeSeries smooth = smoothedIn(pitch, a, leg.end_s);
    const std::vector<double> b = upCrossings(smooth, o.average_min_period_s);
    if (static_cast<int>(b.size()) - 1 < o.average_min_cycles) continue;
    if (b.back() - b.front() < o.average_min_s) continue;
    // A leg its steady windows cover stays with them unless it swings:
    // over a partial cycle their plain means would carry the swing.
    const bool covered = overlap(steady, b.front(), b.back()) > o.average_max_steady_cover * (b.back() - b.front());
    if (covered && !(sdOf(smooth.v) >= o.average_min_swing_deg)) continue;
    Segment s{SegmentKind::kSteady, b.front(), b.back(), SegmentKind::kLevel, b};
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Segment> auvSteadyGlides(const MissionLog& log, const std::vector<Segment>& phases, const SegmentOptions& o) {
  std::vector<Segment> out;
  if (!log.has("pitch")) return out;
  const TimeSeries pitch = log.series("pitch");
  std::vector<TimeWindow> vertical;
  for (const Segment& p : phases) {
    if (p.kind != SegmentKind::kDive && p.kind != SegmentKind::kClimb) continue;
    const std::optional<TimeWindow> plateau = pitchPlateau(pitch, p.start_s, p.end_s, o.auv_glide_plateau_deg);
    if (plateau && plateau->start_s + 2 * o.auv_glide_settle_s < plateau->end_s)
      vertical.push_back({plateau->start_s + o.auv_glide_settle_s, plateau->end_s - o.auv_glide_settle_s});
  }
  for (const TimeWindow& w : vertical) {
    if (w.duration() < o.auv_glide_min_s) continue;
    if (!(sdOf(smoothedIn(pitch, w.start_s, w.end_s).v) <= o.auv_glide_max_pitch_sd_deg)) continue;
    SegmentKind phase = SegmentKind::kDive;
    for (const Segment& p : phases)
      if (p.start_s <= w.start_s && w.end_s <= p.end_s) phase = p.kind;
    out.push_back({SegmentKind::kGlide, w.start_s, w.end_s, phase, {}});
  }
  return out;
}

MeanEstimate cycleMean(const TimeSeries& s, std::span<const double> bounds) {
  MeanEstimate m;
  if (bounds.size() < 3) return m;
  std::vector<double> cyc;
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0;
  std::size_t i = std::lower_bound(s.t.begin(), s.t.end(), bounds.front()) - s.t.begin();
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    double cs = 0.0;
    std::size_t cn = 0;
    for (; i < s.size() && s.t[i] < bounds[k + 1]; ++i) {
      if (std::isnan(s.v[i])) continue;
      cs += s.v[i];
      sum += s.v[i];
      sum2 += s.v[i] * s.v[i];
      ++cn;
    }
    if (cn > 0) cyc.push_back(cs / static_cast<double>(cn));
    n += cn;
  }
  if (cyc.size() < 2 || n < 2) return m;
  m.n = n;
  m.mean = sum / static_cast<double>(n);
  m.sd = std::sqrt(std::max(0.0, (sum2 - sum * m.mean) / static_cast<double>(n - 1)));
  const double k = static_cast<double>(cyc.size());
  double between = 0.0, cm = 0.0;
  for (double c : cyc) cm += c;
  cm /= k;
  for (double c : cyc) between += (c - cm) * (c - cm);
  between /= (k - 1.0);
  m.se = std::max(std::sqrt(between / k), kPhaseErrorFrac * m.sd / k);
  m.ci95 = 1.96 * m.se;
  m.blocks = cyc.size();
  m.n_eff = m.se > 0.0 ? std::pow(m.sd / m.se, 2) : static_cast<double>(n);
  m.lag1 = 0.0;
  return m;
}

std::optional<BalanceRegressors> cycleRegressors(const MissionLog& log, const TimeSeries& depth_rate,
                                                 std::span<const double> bounds) {
  if (bounds.size() < 2) return std::nullopt;
  const TimeSeries pitch = log.series("pitch"), speed = log.series("speed");
  const TimeSeries roll = log.has("roll") ? log.series("roll") : TimeSeries{};
  const TimeSeries elev = log.has("elevator") ? log.series("elevator") : TimeSeries{};
  constexpr double kGap_s = 30.0;
  SeriesCursor u(speed, false, kGap_s), phi(roll, false, kGap_s), zr(depth_rate, false, kGap_s), e(elev, false, kGap_s);
  const double d2r = std::acos(-1.0) / 180.0;
  BalanceRegressors sum{0, 0, 0, 0, 0, 0, 0};
  std::size_t n = 0;
  for (std::size_t i = 0; i < pitch.size() && pitch.t[i] < bounds.back(); ++i) {
    const double t = pitch.t[i];
    if (t < bounds.front()) continue;
    const double ui = u.at(t), zi = zr.at(t);
    const double ph = roll.empty() ? 0.0 : phi.at(t) * d2r, ei = elev.empty() ? 0.0 : e.at(t);
    if (!std::isfinite(ui) || !std::isfinite(zi) || !std::isfinite(ph) || !std::isfinite(ei)) continue;
    const BalanceRegressors r = balanceRegressors({ui, pitch.v[i] * d2r, ph, ei, zi});
    sum.cc += r.cc, sum.sin_theta += r.sin_theta, sum.au_w += r.au_w, sum.u_w += r.u_w;
    sum.aw_w += r.aw_w, sum.au_u += r.au_u, sum.au_u_e += r.au_u_e;
    ++n;
  }
  if (n == 0) return std::nullopt;
  const double k = 1.0 / static_cast<double>(n);
  return BalanceRegressors{sum.cc * k, sum.sin_theta * k, sum.au_w * k, sum.u_w * k, sum.aw_w * k, sum.au_u * k, sum.au_u_e * k};
}

void averageOverCycles(const MissionLog& log, const Segment& leg, const TimeSeries& depth_rate, const TimeSeries& fast_rate,
                       SteadySegmentMeans& m) {
  const std::span<const double> b = leg.cycle_bounds_s;
  auto over = [&](const char* channel, MeanEstimate& e) {
    if (log.has(channel)) e = cycleMean(log.series(channel), b);
  };
  over("speed", m.speed_mps);
  over("pitch", m.pitch_deg);
  over("roll", m.roll_deg);
  over("elevator", m.elevator_deg);
  over("prop_rpm", m.prop_rpm);
  m.depth_rate_mps = cycleMean(depth_rate, b);
  if (log.has("pitch") && log.has("speed")) m.regressors = cycleRegressors(log, fast_rate, b);
}

}  // namespace auv::analysis
