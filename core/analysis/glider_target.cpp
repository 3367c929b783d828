#include "analysis/glider_target.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/input_error.h"
#include "seawater/seawater.h"

namespace auv::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Linear interpolation of a series at t (NaN outside it or across a gap).
double at(const TimeSeries& s, double t, double max_gap_s) {
  if (s.empty() || t < s.t.front() || t > s.t.back()) return kNaN;
  const auto it = std::lower_bound(s.t.begin(), s.t.end(), t);
  const auto k = static_cast<std::size_t>(it - s.t.begin());
  if (s.t[k] == t) return s.v[k];
  if (k == 0 || s.t[k] - s.t[k - 1] > max_gap_s) return kNaN;
  const double f = (t - s.t[k - 1]) / (s.t[k] - s.t[k - 1]);
  return s.v[k - 1] + f * (s.v[k] - s.v[k - 1]);
}

// Depth (m) on its own time base: pressure converted when the log has it,
// else the depth channel.
TimeSeries depthOf(const MissionLog& log, double latitude) {
  const LogChannel* p = log.find("pressure");
  const LogChannel* d = log.find("depth");
  if (p && p->validCount() >= 2 && (!d || p->validCount() >= d->validCount())) {
    TimeSeries s = log.series("pressure");
    for (double& x : s.v) x = seawater::depthFromPressure(std::clamp(x, 0.0, 11000.0), latitude);
    return s;
  }
  if (d && d->validCount() >= 2) return log.series("depth");
  throw InputError("target", "the log has neither depth nor pressure", "give --target-density, --target-pressure and --target-temperature");
}

struct WaterMeans {
  double T = kNaN, S = kNaN, rho = kNaN, z = kNaN;
  std::size_t n = 0;
};

// Mean CTD water over the temperature samples accepted by `keep(t, z)`.
template <class Keep>
WaterMeans meanWater(const MissionLog& log, const TimeSeries& depth, Keep keep) {
  WaterMeans w;
  if (!log.has("temperature")) return w;
  const TimeSeries T = log.series("temperature");
  const TimeSeries S = log.has("salinity") ? log.series("salinity") : TimeSeries{};
  const TimeSeries R = log.has("density") ? log.series("density") : TimeSeries{};
  double sT = 0, sS = 0, sR = 0, sz = 0;
  std::size_t nS = 0, nR = 0;
  for (std::size_t i = 0; i < T.size(); ++i) {
    const double z = at(depth, T.t[i], 120.0);
    if (!std::isfinite(z) || !std::isfinite(T.v[i]) || !keep(T.t[i], z)) continue;
    sT += T.v[i];
    sz += z;
    ++w.n;
    const double s = at(S, T.t[i], 120.0);
    if (std::isfinite(s)) {
      sS += s;
      ++nS;
    }
    const double r = at(R, T.t[i], 120.0);
    if (std::isfinite(r)) {
      sR += r;
      ++nR;
    }
  }
  if (w.n == 0) return w;
  w.T = sT / static_cast<double>(w.n);
  w.z = sz / static_cast<double>(w.n);
  if (nS > 0) w.S = sS / static_cast<double>(nS);
  if (nR > 0) w.rho = sR / static_cast<double>(nR);
  return w;
}

void requireIn(std::optional<double> v, double lo, double hi, const char* flag, const char* example) {
  if (v && !(*v >= lo && *v <= hi))
    throw InputError(flag, "must lie between " + fmt("%g", lo) + " and " + fmt("%g", hi), std::string("e.g. --") + flag + " " + example);
}

}  // namespace

GliderTarget resolveGliderTarget(const MissionLog& log, const GliderTargetRequest& q, double latitude) {
  requireIn(q.density_kgm3, 990.0, 1080.0, "target-density", "1027.3");
  requireIn(q.pressure_dbar, 0.0, 7000.0, "target-pressure", "500");
  requireIn(q.temperature_degC, -2.5, 40.0, "target-temperature", "8.5");
  requireIn(q.depth_m, 0.0, 7000.0, "target-depth", "500");
  GliderTarget g;
  g.salinity_psu = kNaN;
  const bool complete = q.density_kgm3 && q.pressure_dbar && q.temperature_degC;
  WaterMeans w;
  std::string base;
  if (!complete) {
    const TimeSeries depth = depthOf(log, latitude);
    if (q.depth_m) {
      const double zt = *q.depth_m;
      w = meanWater(log, depth, [&](double, double z) { return std::abs(z - zt) <= 2.5; });
      double zmax = 0.0;
      for (double z : depth.v) zmax = std::max(zmax, std::isfinite(z) ? z : 0.0);
      if (w.n == 0)
        throw InputError("target-depth", "the log has no CTD sample within 2.5 m of " + fmt("%.1f", zt) + " m (it reaches " +
                                             fmt("%.1f", zmax) + " m)",
                         "give a depth the log reached, or --target-density/--target-pressure/--target-temperature");
      w.z = zt;
      if (!std::isfinite(w.S)) {
        // Salinity blanked there by QC: take it from a wider band.
        w.S = meanWater(log, depth, [&](double, double z) { return std::abs(z - zt) <= 25.0; }).S;
      }
      base = "the log's own CTD at " + fmt("%.1f", zt) + " m (" + std::to_string(w.n) + " samples within 2.5 m)";
    } else {
      // The bottom of the deepest yo: CTD samples within 5 m of the deepest
      // one and 20 min of its time (the CTD may pause at the apogee).
      double zmax = -1.0, tmax = 0.0;
      meanWater(log, depth, [&](double t, double z) {
        if (z > zmax) {
          zmax = z;
          tmax = t;
        }
        return false;
      });
      w = meanWater(log, depth, [&](double t, double z) { return z >= zmax - 5.0 && std::abs(t - tmax) <= 1200.0; });
      if (w.n == 0)
        throw InputError("target", "the log has no CTD temperature with a depth to place it",
                         "give --target-density, --target-pressure and --target-temperature");
      if (!std::isfinite(w.S)) w.S = meanWater(log, depth, [&](double, double z) { return z >= zmax - 25.0; }).S;
      base = "the log's own water at the bottom of its deepest yo (" + fmt("%.1f", w.z) + " m, " + std::to_string(w.n) +
             " CTD samples within 5 m of " + fmt("%.1f", zmax) + " m)";
    }
  }
  g.pressure_dbar = q.pressure_dbar.value_or(complete ? 0.0 : seawater::pressureFromDepth(std::max(0.0, w.z), latitude));
  g.temperature_degC = q.temperature_degC.value_or(w.T);
  g.salinity_psu = w.S;
  if (q.density_kgm3) {
    g.density_kgm3 = *q.density_kgm3;
  } else if (std::isfinite(w.S)) {
    g.density_kgm3 = seawater::density(w.S, g.temperature_degC, g.pressure_dbar);
  } else if (std::isfinite(w.rho) && !q.pressure_dbar && !q.temperature_degC) {
    g.density_kgm3 = w.rho;
  } else {
    throw InputError("target-density", "the log has no salinity to compute the target density from",
                     "give --target-density KG_M3");
  }
  std::string given;
  auto add = [&](bool has, const char* what) {
    if (has) given += (given.empty() ? "" : ", ") + std::string(what);
  };
  add(q.density_kgm3.has_value(), "density");
  add(q.pressure_dbar.has_value(), "pressure");
  add(q.temperature_degC.has_value(), "temperature");
  if (complete)
    g.basis = "as given (density, pressure, temperature)";
  else if (given.empty())
    g.basis = base;
  else
    g.basis = given + " as given; the rest from " + base;
  return g;
}

double gliderMassToAddKg(double V0_m3, double kappa, double alpha, double T_ref, const GliderTarget& t, double mass_now_kg) {
  const double V = V0_m3 * (1.0 - kappa * t.pressure_dbar) * (1.0 + alpha * (t.temperature_degC - T_ref));
  return t.density_kgm3 * V - mass_now_kg;
}

}  // namespace auv::analysis
