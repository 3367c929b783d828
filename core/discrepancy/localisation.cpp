#include "discrepancy/localisation.h"

#include "discrepancy/check_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

namespace auv::discrepancy {

const char* phaseName(Phase p) {
  switch (p) {
    case Phase::kSurface: return "surface";
    case Phase::kDive: return "dive";
    case Phase::kClimb: return "climb";
    case Phase::kLevel: return "level";
    case Phase::kTurn: return "turn";
  }
  return "?";
}

int SampleTable::unitCount() const {
  int m = -1;
  for (int u : unit) m = std::max(m, u);
  return m + 1;
}

namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// A number with about three significant digits, no trailing noise.
std::string num(double v) {
  const double a = std::abs(v);
  if (a == 0.0) return "0";
  if (a >= 100) return fmt("%.0f", v);
  if (a >= 10) return fmt("%.1f", v);
  if (a >= 1) return fmt("%.2f", v);
  if (a >= 0.01) return fmt("%.3f", v);
  return fmt("%.2g", v);
}

std::string channelWords(Channel c) {
  switch (c) {
    case Channel::kVerticalVelocity: return "vertical-velocity error";
    case Channel::kVerticalForce: return "vertical-force error";
    case Channel::kPitchMoment: return "pitch-moment error";
    case Channel::kRollMoment: return "roll-moment error";
    case Channel::kDepth: return "depth error";
    case Channel::kPitch: return "pitch error";
    case Channel::kRoll: return "roll error";
    case Channel::kSpeed: return "speed error";
    case Channel::kSurgeForce: return "surge-force error";
  }
  return "error";
}

struct NumericFactor {
  const char* name;
  const std::vector<double>* x;
  double step;           // display step of the trend
  const char* step_text;  // "100 dbar"
  const char* unit;       // for band labels
  const char* above;      // words for x > x0 ("below", for pressure = deeper)
  const char* below;
  const char* words;  // the factor's name in a sentence
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// eta^2 and bin summaries for a grouping of the rows.
double etaSquared(const std::vector<double>& y, const std::vector<int>& group, int G, std::vector<BinSummary>& bins) {
  std::vector<double> s(static_cast<std::size_t>(G), 0.0), s2(static_cast<std::size_t>(G), 0.0);
  std::vector<std::size_t> n(static_cast<std::size_t>(G), 0);
  double tot = 0.0, tot2 = 0.0;
  std::size_t N = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (group[i] < 0) continue;
    const auto g = static_cast<std::size_t>(group[i]);
    s[g] += y[i];
    s2[g] += y[i] * y[i];
    ++n[g];
    tot += y[i];
    tot2 += y[i] * y[i];
    ++N;
  }
  if (N < 10) return 0.0;
  const double mean = tot / static_cast<double>(N);
  const double ss = tot2 - static_cast<double>(N) * mean * mean;
  double between = 0.0;
  int used = 0;
  for (std::size_t g = 0; g < static_cast<std::size_t>(G); ++g) {
    bins[g].count = n[g];
    if (n[g] == 0) continue;
    const double m = s[g] / static_cast<double>(n[g]);
    bins[g].mean = m;
    bins[g].rms = std::sqrt(s2[g] / static_cast<double>(n[g]));
    between += static_cast<double>(n[g]) * (m - mean) * (m - mean);
    if (n[g] >= 5) ++used;
  }
  if (used < 2 || !(ss > 0.0)) return 0.0;
  return std::clamp(between / ss, 0.0, 1.0);
}

}  // namespace

Localisation localise(const SampleTable& s, std::span<const double> value, Channel ch, const std::string& source) {
  Localisation L;
  L.channel = ch;
  L.source = source;
  const double k = channelDisplayScale(ch);
  const std::string unit = channelUnit(ch);
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < s.size() && i < value.size(); ++i)
    if (std::isfinite(value[i])) rows.push_back(i);
  L.count = rows.size();
  if (rows.size() < 20) {
    L.summary = "too few samples to localise";
    return L;
  }
  std::vector<double> y(rows.size());
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    y[j] = value[rows[j]] * k;
    sum += y[j];
    sum2 += y[j] * y[j];
  }
  const double n = static_cast<double>(rows.size());
  L.mean = sum / n;
  L.rms = std::sqrt(sum2 / n);
  const double sd = std::sqrt(std::max(0.0, sum2 / n - L.mean * L.mean));
  const std::string what = channelWords(ch);

  // A residual that hardly varies is a constant offset: say so.
  if (sd < 0.05 * std::abs(L.mean)) {
    L.summary = Message(msg::kConstant, {what, num(L.mean), unit});
    return L;
  }

  std::vector<double> hours(s.t.size());
  for (std::size_t i = 0; i < s.t.size(); ++i) hours[i] = s.t[i] / 3600.0;
  const NumericFactor numeric[] = {
      {"pressure", &s.pressure_dbar, 100.0, "100 dbar", "dbar", "below", "above", "pressure"},
      {"temperature", &s.temperature_degC, 1.0, "degC", "degC", "above", "below", "temperature"},
      {"time", &hours, 1.0, "hour", "h", "after", "before", "time"},
      {"speed", &s.speed_mps, 0.1, "0.1 m/s", "m/s", "above", "below", "speed"},
      {"rpm", &s.rpm, 100.0, "100 rpm", "rpm", "above", "below", "propeller speed"},
      {"pitch", &s.pitch_deg, 10.0, "10 deg of pitch", "deg", "above", "below", "pitch"},
      {"since_actuator_change", &s.since_actuator_s, 10.0, "10 s since an actuator change", "s", "after", "within",
       "time since an actuator change"},
  };

  for (const NumericFactor& f : numeric) {
    if (f.x->size() != s.size()) continue;
    std::vector<double> xs, yy;
    for (std::size_t j = 0; j < rows.size(); ++j) {
      const double x = (*f.x)[rows[j]];
      if (std::isfinite(x)) {
        xs.push_back(x);
        yy.push_back(y[j]);
      }
    }
    if (xs.size() < 20) continue;
    const double x0 = quantile(xs, 0.0), x1 = quantile(xs, 1.0);
    if (!(x1 - x0 > 1e-9 * std::max(1.0, std::abs(x1)))) continue;
    // Six quantile bins (edges merged where the factor has few values).
    std::vector<double> edges;
    for (int b = 1; b < 6; ++b) {
      const double e = quantile(xs, b / 6.0);
      if (edges.empty() || e > edges.back()) edges.push_back(e);
    }
    const int G = static_cast<int>(edges.size()) + 1;
    std::vector<int> grp(xs.size());
    for (std::size_t j = 0; j < xs.size(); ++j)
      grp[j] = static_cast<int>(std::upper_bound(edges.begin(), edges.end(), xs[j]) - edges.begin());
    FactorFinding ff;
    ff.factor = f.name;
    ff.bins.resize(static_cast<std::size_t>(G));
    for (int g = 0; g < G; ++g) {
      const double lo = g == 0 ? x0 : edges[static_cast<std::size_t>(g - 1)];
      const double hi = g == G - 1 ? x1 : edges[static_cast<std::size_t>(g)];
      ff.bins[static_cast<std::size_t>(g)].label = num(lo) + "-" + num(hi) + " " + f.unit;
    }
    ff.share = etaSquared(yy, grp, G, ff.bins);
    // Line and one-sided hinge fits.
    auto fitLine = [&](const std::function<double(double)>& basis, double& a, double& b) {
      double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
      for (std::size_t j = 0; j < xs.size(); ++j) {
        const double u = basis(xs[j]);
        sx += u;
        sy += yy[j];
        sxx += u * u;
        sxy += u * yy[j];
        m += 1;
      }
      const double d = m * sxx - sx * sx;
      if (!(std::abs(d) > 1e-300)) {
        a = sy / m;
        b = 0;
      } else {
        b = (m * sxy - sx * sy) / d;
        a = (sy - b * sx) / m;
      }
      double rss = 0;
      for (std::size_t j = 0; j < xs.size(); ++j) {
        const double e = yy[j] - a - b * basis(xs[j]);
        rss += e * e;
      }
      return rss;
    };
    double a = 0, b = 0;
    double ym = 0;
    for (double v : yy) ym += v;
    ym /= static_cast<double>(yy.size());
    double tss = 0;
    for (double v : yy) tss += (v - ym) * (v - ym);
    const double rssLine = fitLine([](double x) { return x; }, a, b);
    const double r2 = tss > 0 ? 1.0 - rssLine / tss : 0.0;
    double bestRss = rssLine, bestB = b, bestX = std::numeric_limits<double>::quiet_NaN();
    bool aboveHinge = true;
    // Hinge positions: 24 quantiles of the factor (the bin edges are too coarse).
    std::vector<double> hinges;
    {
      std::vector<double> sorted = xs;
      std::sort(sorted.begin(), sorted.end());
      for (int q = 1; q < 25; ++q) {
        const double e = sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1) / 25.0)];
        if (hinges.empty() || e > hinges.back()) hinges.push_back(e);
      }
    }
    for (double e : hinges) {
      for (int side = 0; side < 2; ++side) {
        double ha = 0, hb = 0;
        const double rss = side == 0 ? fitLine([e](double x) { return std::max(0.0, x - e); }, ha, hb)
                                     : fitLine([e](double x) { return std::min(0.0, x - e); }, ha, hb);
        if (rss < 0.85 * bestRss) {
          bestRss = rss;
          bestB = hb;
          bestX = e;
          aboveHinge = side == 0;
        }
      }
    }
    const double r2best = tss > 0 ? 1.0 - bestRss / tss : 0.0;
    if (r2best >= 0.6 * ff.share && r2best > 0.02) {
      ff.linear = true;
      ff.slope = bestB * f.step;
      ff.step = f.step_text;
      // "grows" when the error moves away from zero as the factor increases.
      const bool grows = (bestB > 0) == (ym + bestB * (x1 - x0) / 2 > 0) || std::abs(ym) < 1e-12;
      const std::string size = num(std::abs(ff.slope)), signed_size = (bestB > 0 ? "+" : "-") + size;
      const std::string variance = fmt("%.0f", 100 * std::max(r2, r2best));
      if (std::isnan(bestX))
        ff.text = Message(grows ? msg::kGrows : msg::kShrinks, {what, size, unit, f.step_text, signed_size, variance});
      else
        ff.text = Message(grows ? msg::kGrowsBeyond : msg::kShrinksBeyond,
                          {what, size, unit, f.step_text, aboveHinge ? f.above : f.below, num(bestX), f.unit,
                           signed_size, variance});
    } else {
      std::size_t gmax = 0;
      for (std::size_t g = 0; g < ff.bins.size(); ++g)
        if (std::abs(ff.bins[g].mean - ym) > std::abs(ff.bins[gmax].mean - ym) && ff.bins[g].count >= 5) gmax = g;
      ff.text = Message(msg::kConcentrates, {what, f.words, ff.bins[gmax].label, num(ff.bins[gmax].mean), unit, num(ym)});
    }
    L.ranked.push_back(ff);
  }

  // Phase (categorical).
  {
    FactorFinding ff;
    ff.factor = "phase";
    const int G = 5;
    ff.bins.resize(G);
    for (int g = 0; g < G; ++g) ff.bins[static_cast<std::size_t>(g)].label = phaseName(static_cast<Phase>(g));
    std::vector<int> grp(rows.size());
    for (std::size_t j = 0; j < rows.size(); ++j) grp[j] = static_cast<int>(s.phase[rows[j]]);
    ff.share = etaSquared(y, grp, G, ff.bins);
    std::size_t gmax = 0;
    for (std::size_t g = 0; g < ff.bins.size(); ++g)
      if (ff.bins[g].count >= 5 && (ff.bins[gmax].count < 5 || std::abs(ff.bins[g].mean) > std::abs(ff.bins[gmax].mean)))
        gmax = g;
    std::vector<std::string> args{what, ff.bins[gmax].label + "s", num(ff.bins[gmax].mean), unit};
    std::string others;
    for (std::size_t g = 0; g < ff.bins.size(); ++g)
      if (g != gmax && ff.bins[g].count >= 5) {
        others += (others.empty() ? "" : ", ") + ff.bins[g].label + "s " + num(ff.bins[g].mean);
        args.push_back(ff.bins[g].label + "s");
        args.push_back(num(ff.bins[g].mean));
      }
    std::string english = what + " is largest during " + args[1] + ": mean " + args[2] + " " + unit +
                          (others.empty() ? "" : " (" + others + ")");
    ff.text = Message(msg::kLargestDuring, std::move(english), std::move(args));
    ff.bins.erase(std::remove_if(ff.bins.begin(), ff.bins.end(), [](const BinSummary& b) { return b.count == 0; }),
                  ff.bins.end());
    if (ff.bins.size() >= 2) L.ranked.push_back(ff);
  }

  // Largest share first; on a tie (e.g. pitch sign = phase) the mission phase
  // is the plainer description.
  std::stable_sort(L.ranked.begin(), L.ranked.end(), [](const FactorFinding& p, const FactorFinding& q) {
    if (std::abs(p.share - q.share) > 1e-9) return p.share > q.share;
    return p.factor == "phase" && q.factor != "phase";
  });
  if (L.ranked.empty()) {
    L.summary = Message(msg::kNoFactor, {what});
    return L;
  }
  // Name what it does not depend on: the technician's first suspects.
  std::string independent;
  for (const char* cand : {"speed", "rpm", "time"}) {
    for (const FactorFinding& f : L.ranked)
      if (independent.empty() && f.factor == cand && f.share < 0.03 && f.factor != L.ranked.front().factor)
        independent = f.factor == "rpm" ? "propeller speed" : f.factor;
  }
  const Message& top = L.ranked.front().text;
  std::vector<std::string> args{top.id()};
  args.insert(args.end(), top.args().begin(), top.args().end());
  args.push_back(independent);
  std::string english = top.text() + (independent.empty() ? "" : "; independent of " + independent);
  L.summary = Message(msg::kSummary, std::move(english), std::move(args));
  return L;
}

}  // namespace auv::discrepancy
