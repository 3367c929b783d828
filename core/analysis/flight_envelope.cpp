#include "analysis/flight_envelope.h"

#include <cstdio>
#include <string>

#include "analysis/analysis_messages.h"
#include "analysis/analysis_report.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace auv::analysis {

namespace {

// Samples of s with t in [a, b].
std::pair<std::size_t, std::size_t> indexRange(const TimeSeries& s, double a, double b) {
  const auto lo = std::lower_bound(s.t.begin(), s.t.end(), a) - s.t.begin();
  const auto hi = std::upper_bound(s.t.begin(), s.t.end(), b) - s.t.begin();
  return {static_cast<std::size_t>(lo), static_cast<std::size_t>(hi)};
}

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The elevator's stop: the extreme |value| when at least min_stop_fraction
// of the samples sit within stop_band_deg of it (a clipped signal).
std::optional<double> elevatorStop(const TimeSeries& e, const EnvelopeOptions& o) {
  double ext = 0.0;
  std::size_t n = 0;
  for (double x : e.v)
    if (std::isfinite(x)) {
      ext = std::max(ext, std::abs(x));
      ++n;
    }
  if (n == 0 || ext < o.min_stop_deg) return std::nullopt;
  std::size_t at = 0;
  for (double x : e.v)
    if (std::isfinite(x) && std::abs(x) >= ext - o.stop_band_deg) ++at;
  if (static_cast<double>(at) < o.min_stop_fraction * static_cast<double>(n)) return std::nullopt;
  return ext;
}

double coveredSeconds(const std::vector<Segment>& w, double a, double b) {
  double s = 0.0;
  for (const Segment& x : w) s += std::max(0.0, std::min(b, x.end_s) - std::max(a, x.start_s));
  return s;
}

struct PitchSwing {
  double sd = 0.0, period_s = std::numeric_limits<double>::quiet_NaN();
};

// Standard deviation of the pitch over [a, b] and the mean period between
// its up-crossings of the mean (hysteresis 0.3 sd, so noise is no cycle).
PitchSwing pitchSwing(const TimeSeries& p, double a, double b) {
  PitchSwing out;
  const auto [lo, hi] = indexRange(p, a, b);
  double s1 = 0.0, s2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = lo; i < hi; ++i)
    if (std::isfinite(p.v[i])) {
      s1 += p.v[i];
      s2 += p.v[i] * p.v[i];
      ++n;
    }
  if (n < 3) return out;
  const double m = s1 / static_cast<double>(n);
  out.sd = std::sqrt(std::max(0.0, (s2 - s1 * m) / static_cast<double>(n - 1)));
  const double h = 0.3 * out.sd;
  int state = 0;
  std::vector<double> ups;
  for (std::size_t i = lo; i < hi; ++i) {
    const double x = p.v[i];
    if (!std::isfinite(x)) continue;
    if (x < m - h) state = -1;
    if (x > m + h) {
      if (state == -1) ups.push_back(p.t[i]);
      state = 1;
    }
  }
  if (ups.size() >= 3) out.period_s = (ups.back() - ups.front()) / static_cast<double>(ups.size() - 1);
  return out;
}

void addNotHeld(std::optional<DepthNotHeld>& f, double seconds, double err_m, double stop_deg, std::vector<double>& errs) {
  if (!f) f = DepthNotHeld{};
  f->seconds += seconds;
  f->elevator_stop_deg = stop_deg;
  ++f->legs;
  errs.push_back(err_m);
  f->depth_error_m = median(errs);
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

FlightEnvelope flightEnvelope(const MissionLog& log, const TimeSeries& depth, const std::vector<TimeWindow>& command_cuts,
                              const std::vector<Segment>& operating, const SegmentOptions& so, const EnvelopeOptions& o) {
  FlightEnvelope out;
  if (depth.size() < 2 || !log.has("depth_cmd")) return out;
  const TimeSeries cmd = log.series("depth_cmd");
  const TimeSeries pitch = log.has("pitch") ? log.series("pitch") : TimeSeries{};
  const TimeSeries elev = log.has("elevator") ? log.series("elevator") : TimeSeries{};
  const std::optional<double> found_stop = elev.empty() ? std::nullopt : elevatorStop(elev, o);
  const bool has_stop = found_stop.has_value();
  const double stop_deg = found_stop.value_or(0.0);
  std::vector<TimeWindow> cuts = command_cuts;
  for (std::size_t i = 1; i < depth.size(); ++i)
    if (depth.t[i] - depth.t[i - 1] > so.max_gap_s) cuts.push_back({depth.t[i - 1], depth.t[i]});
  const std::vector<TimeWindow> legs = subtractWindows({{depth.t.front(), depth.t.back()}}, mergeWindows(std::move(cuts)));
  std::vector<double> light_err, heavy_err, periods;
  for (const TimeWindow& leg : legs) {
    const double a = leg.start_s + o.settle_s, b = leg.end_s;
    if (b - a < o.min_leg_s) continue;
    out.leg_seconds += b - a;
    if (has_stop) {
      const auto [lo, hi] = indexRange(elev, a, b);
      std::size_t at = 0, n = 0;
      for (std::size_t i = lo; i < hi; ++i)
        if (std::isfinite(elev.v[i])) {
          ++n;
          if (std::abs(elev.v[i]) >= stop_deg - o.stop_band_deg) ++at;
        }
      const auto [dlo, dhi] = indexRange(depth, a, b);
      SeriesCursor c(cmd, true, std::numeric_limits<double>::infinity());
      std::vector<double> err;
      for (std::size_t i = dlo; i < dhi; ++i) {
        const double zc = c.at(depth.t[i]);
        if (std::isfinite(zc) && std::isfinite(depth.v[i])) err.push_back(depth.v[i] - zc);
      }
      const double e = median(err);
      if (n > 0 && static_cast<double>(at) >= o.at_stop_fraction * static_cast<double>(n) && std::abs(e) >= o.depth_error_m) {
        if (e < 0) addNotHeld(out.too_light, b - a, e, stop_deg, light_err);
        else addNotHeld(out.too_heavy, b - a, e, stop_deg, heavy_err);
        continue;  // a leg off its command at the stop is not also called porpoising
      }
    }
    if (pitch.empty()) continue;
    const PitchSwing sw = pitchSwing(pitch, a, b);
    if (sw.sd < o.porpoise_pitch_sd_deg || coveredSeconds(operating, a, b) > o.porpoise_max_steady_cover * (b - a)) continue;
    if (!out.porpoising) out.porpoising = Porpoising{};
    out.porpoising->seconds += b - a;
    out.porpoising->pitch_sd_deg = std::max(out.porpoising->pitch_sd_deg, sw.sd);
    ++out.porpoising->legs;
    if (std::isfinite(sw.period_s)) periods.push_back(sw.period_s);
  }
  if (out.porpoising) out.porpoising->period_s = median(periods);
  return out;
}

// Legs not flown as commanded: a warning each, and details.flight_envelope.
void reportFlightEnvelope(const FlightEnvelope& e, AnalysisReport& rep) {
  nlohmann::json d = {{"leg_s", e.leg_seconds}};
  auto notHeld = [&](const std::optional<DepthNotHeld>& f, const MessageFormat& m, const char* key) {
    if (!f) return;
    rep.warnings.push_back(Message(m, {fmt("%.0f", f->seconds / 60.0), fmt("%.1f", std::abs(f->depth_error_m)),
                                       fmt("%.1f", f->elevator_stop_deg)}));
    d[key] = {{"legs", f->legs}, {"seconds", f->seconds}, {"median_depth_error_m", f->depth_error_m},
              {"elevator_stop_deg", f->elevator_stop_deg}};
  };
  notHeld(e.too_light, msg::kDepthNotHeldLight, "too_light");
  notHeld(e.too_heavy, msg::kDepthNotHeldHeavy, "too_heavy");
  if (e.porpoising) {
    const Porpoising& p = *e.porpoising;
    rep.warnings.push_back(Message(msg::kPorpoising, {std::to_string(p.legs), fmt("%.0f", p.seconds / 60.0),
                                                      fmt("%.0f", p.pitch_sd_deg), std::isfinite(p.period_s) ? fmt("%.0f", p.period_s) : "?"}));
    d["porpoising"] = {{"legs", p.legs}, {"seconds", p.seconds}, {"pitch_sd_deg", p.pitch_sd_deg}, {"period_s", std::isfinite(p.period_s) ? nlohmann::json(p.period_s) : nlohmann::json(nullptr)}};
  }
  rep.details["flight_envelope"] = d;
}

}  // namespace auv::analysis
