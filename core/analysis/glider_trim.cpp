#include "analysis/glider_trim.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "analysis/series_tools.h"
#include "common/units.h"

namespace auv::analysis {

namespace {

bool has(const MissionLog& log, const char* name) {
  const LogChannel* c = log.find(name);
  return c && c->validCount() >= 10;
}

}  // namespace

GliderTrim estimateGliderTrim(const MissionLog& log, const std::vector<Segment>& glides) {
  GliderTrim g;
  if (glides.empty()) {
    g.pitch_why_not = g.roll_why_not = "no steady glide in the log";
    return g;
  }
  // Pitch trim: least squares on every pitch sample inside a glide.
  if (!has(log, "pitch") || !has(log, "pump_volume") || !has(log, "battery_position")) {
    g.pitch_why_not = "the log lacks pitch, pump_volume or battery_position";
  } else {
    const TimeSeries p = log.series("pitch");
    const TimeSeries pump = log.series("pump_volume"), batt = log.series("battery_position");
    // Banked turns (a Seaglider turns at 50-60 deg of roll) pitch differently: 2-D samples only.
    const TimeSeries roll = has(log, "roll") ? log.series("roll") : TimeSeries{};
    SeriesCursor cPump(pump, false, 120.0), cBatt(batt, true, 1e9), cRoll(roll, false, 120.0);
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector4d> rows;
    g.battery_min_mm = 1e300;
    g.battery_max_mm = -1e300;
    std::size_t w = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      while (w < glides.size() && glides[w].end_s < p.t[i]) ++w;
      if (w == glides.size()) break;
      if (p.t[i] < glides[w].start_s) continue;
      const double q = cPump.at(p.t[i]), x = cBatt.at(p.t[i]);
      if (!std::isfinite(q) || !std::isfinite(x) || !std::isfinite(p.v[i]) || std::abs(p.v[i]) > 60.0) continue;
      if (!roll.empty() && std::abs(cRoll.at(p.t[i])) > 15.0) continue;
      const Eigen::Vector3d r(q, x, 1.0);
      const double y = std::tan(units::degToRad(p.v[i]));
      A += r * r.transpose();
      b += r * y;
      rows.emplace_back(q, x, 1.0, y);
      g.battery_min_mm = std::min(g.battery_min_mm, x);
      g.battery_max_mm = std::max(g.battery_max_mm, x);
    }
    g.pitch_samples = rows.size();
    // Pump and battery must both vary (else T1/T2 are not separable from T3).
    const Eigen::Vector3d T = A.ldlt().solve(b);
    if (rows.size() < 20 || !(std::abs(A.determinant()) > 0) || !T.allFinite() || !(std::abs(T[1]) > 1e-6)) {
      g.pitch_why_not = "the glides do not vary pump and battery enough to fit tan(pitch) = T1 pump + T2 battery + T3";
    } else {
      g.pitch_known = true;
      g.T1_per_cm3 = T[0];
      g.T2_per_mm = T[1];
      g.T3 = T[2];
      double ss = 0;
      for (const auto& r : rows) ss += std::pow(r[3] - (T[0] * r[0] + T[1] * r[1] + T[2]), 2);
      g.rms_tan = std::sqrt(ss / static_cast<double>(rows.size()));
      g.battery_for_level_mm = -T[2] / T[1];
    }
  }
  // Roll at the roll actuator's zero.
  if (!has(log, "roll")) {
    g.roll_why_not = "the log has no roll";
  } else {
    const TimeSeries r = log.series("roll");
    const bool hasCmd = has(log, "roll_mass_cmd");
    const TimeSeries cmd = hasCmd ? log.series("roll_mass_cmd") : TimeSeries{};
    SeriesCursor cCmd(cmd, true, 1e9);
    double s = 0, s2 = 0;
    std::size_t n = 0, w = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      while (w < glides.size() && glides[w].end_s < r.t[i]) ++w;
      if (w == glides.size()) break;
      if (r.t[i] < glides[w].start_s || !std::isfinite(r.v[i]) || std::abs(r.v[i]) > 30.0) continue;
      if (hasCmd) {
        const double c = cCmd.at(r.t[i]);
        if (!(std::abs(c) < 1e-6)) continue;
      }
      s += r.v[i];
      s2 += r.v[i] * r.v[i];
      ++n;
    }
    if (n < 10) {
      g.roll_why_not = hasCmd ? "fewer than 10 roll samples in glides with roll_mass_cmd at 0" : "fewer than 10 roll samples in glides";
    } else {
      g.roll_known = true;
      g.roll_samples = n;
      g.roll_deg = s / static_cast<double>(n);
      const double var = std::max(0.0, s2 / static_cast<double>(n) - g.roll_deg * g.roll_deg);
      // Roll wanders slowly (turns, waves): one independent value per glide.
      g.roll_sigma_deg = std::sqrt(var / static_cast<double>(std::max<std::size_t>(1, glides.size())));
      g.roll_basis = hasCmd ? "mean roll in glides with roll_mass_cmd at 0" : "mean roll in glides (the log has no roll command)";
    }
  }
  return g;
}

}  // namespace auv::analysis
