#include "sim/survey_mission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "common/units.h"

namespace auv::sim {
namespace {

double u01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double between(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * u01(rng); }
int intBetween(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(std::floor(u01(rng) * (hi - lo + 1 - 1e-12)));
}

// `count` distinct levels in [lo, hi] at least `spacing` apart, sorted.
std::vector<double> levels(std::mt19937_64& rng, int count, double lo, double hi, double spacing) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    std::vector<double> v;
    for (int i = 0; i < count; ++i) v.push_back(between(rng, lo, hi));
    std::sort(v.begin(), v.end());
    bool ok = true;
    for (std::size_t i = 1; i < v.size(); ++i) ok = ok && v[i] - v[i - 1] >= spacing;
    if (ok) return v;
  }
  std::vector<double> v;  // evenly spread as a fallback
  for (int i = 0; i < count; ++i) v.push_back(lo + (hi - lo) * (count > 1 ? i / double(count - 1) : 0.5));
  return v;
}

}  // namespace

WaterColumn SurveyMission::water() const {
  WaterColumn w = WaterColumn::fromCast(cast, 400.0, 1.0, latitude_deg);
  w.setInternalWave(internal_wave_amplitude_m, internal_wave_period_s);
  return w;
}

std::string SurveyMission::describe() const {
  std::string s = "survey " + std::to_string(static_cast<int>(std::lround(scenarioDuration(scenario) / 60.0))) +
                  " min, rpm";
  char buf[64];
  for (double r : rpms) std::snprintf(buf, sizeof buf, " %.0f", r), s += buf;
  s += ", depths";
  for (double d : depths_m) std::snprintf(buf, sizeof buf, " %.0f", d), s += buf;
  std::snprintf(buf, sizeof buf, " m, internal wave %.1f m / %.0f min", internal_wave_amplitude_m,
                internal_wave_period_s / 60.0);
  return s + buf;
}

SurveyMission makeSurveyMission(std::uint64_t seed, const SurveyRanges& r) {
  std::mt19937_64 rng(seed * 0xD1B54A32D192ED03ULL + 5);
  SurveyMission m;
  m.seed = seed;
  m.rpms = levels(rng, intBetween(rng, r.speeds_min, r.speeds_max), r.rpm_min, r.rpm_max, r.rpm_spacing);
  for (double& x : m.rpms) x = std::round(x);
  m.depths_m = levels(rng, intBetween(rng, r.depths_min, r.depths_max), r.depth_min_m, r.depth_max_m,
                      r.depth_spacing_m);
  for (double& x : m.depths_m) x = std::round(x);

  // Stratification: mixed layer, thermocline, deep water; salinity rising with depth.
  const double t_surface = between(rng, 8.0, 16.0), t_deep = between(rng, 4.0, 7.5);
  const double s_surface = between(rng, 32.5, 34.5), s_deep = s_surface + between(rng, 0.3, 1.2);
  const double mixed = between(rng, 10.0, 30.0), cline = mixed + between(rng, 20.0, 60.0);
  m.cast = {{0.0, t_surface, s_surface}, {mixed, t_surface - 0.3, s_surface + 0.05},
            {cline, t_deep + 1.0, s_deep - 0.1}, {400.0, t_deep, s_deep}};
  m.internal_wave_amplitude_m = between(rng, 1.0, 5.0);
  m.internal_wave_period_s = between(rng, 600.0, 1800.0);

  // Survey lines: every speed at every depth at least once, then random
  // combinations until the duration is reached; reciprocal headings.
  const double duration = between(rng, r.duration_min_s, r.duration_max_s);
  std::vector<std::pair<double, double>> combos;
  for (double d : m.depths_m)
    for (double n : m.rpms) combos.push_back({d, n});
  std::shuffle(combos.begin(), combos.end(), rng);
  double total = 0.0, heading = between(rng, 0.0, 180.0);
  std::size_t i = 0;
  while (total < duration) {
    const auto [depth, rpm] = i < combos.size() ? combos[i] : combos[rng() % combos.size()];
    DepthLeg leg;
    leg.duration_s = std::min(between(rng, r.line_min_s, r.line_max_s), std::max(300.0, duration - total));
    leg.depth_m = depth;
    leg.prop_demand = rpm;
    heading = std::fmod(heading + 180.0, 360.0);
    leg.heading_rad = units::degToRad(heading);
    m.scenario.legs.push_back(leg);
    total += leg.duration_s;
    ++i;
  }
  m.scenario.initial_depth_m = m.scenario.legs.front().depth_m;
  m.scenario.initial_speed_mps = 1.5;
  m.scenario.initial_heading_rad = m.scenario.legs.front().heading_rad;

  // Noise of survey-grade sensors: pressure 2 cm, INS attitude 0.03-0.08 deg,
  // DVL 1-2 cm/s, CTD at its stated accuracy.
  SensorNoise& n = m.options.noise;
  n.depth_m = 0.02;
  n.pitch_rad = units::degToRad(between(rng, 0.03, 0.08));
  n.roll_rad = units::degToRad(between(rng, 0.03, 0.08));
  n.heading_rad = units::degToRad(0.1);
  n.speed_mps = between(rng, 0.01, 0.02);
  n.temperature_degC = 0.002;
  n.salinity_psu = 0.003;
  n.pressure_dbar = 0.02;
  m.options.trace_interval_s = r.trace_interval_s;
  m.options.seed = rng();
  // A vehicle that cannot hold depth broaches and lies at the surface, as a
  // real one would, instead of flying on through it.
  m.options.surface_model = true;
  return m;
}

void applyDropouts(MissionLog& log, std::uint64_t seed, double fraction) {
  std::mt19937_64 rng(seed * 0x94D049BB133111EBULL + 3);
  const std::size_t n = log.rowCount();
  if (n < 100 || fraction <= 0.0) return;
  const double dt = log.duration() / static_cast<double>(n - 1);
  auto drop = [&](std::initializer_list<const char*> names, double burst_min_s, double burst_max_s) {
    double dropped = 0.0;
    while (dropped < fraction * static_cast<double>(n)) {
      const auto len = static_cast<std::size_t>(std::max(1.0, between(rng, burst_min_s, burst_max_s) / dt));
      const auto start = static_cast<std::size_t>(u01(rng) * static_cast<double>(n - 1));
      for (const char* name : names)
        if (LogChannel* c = log.find(name))
          for (std::size_t k = start; k < std::min(n, start + len); ++k)
            c->values[k] = std::numeric_limits<double>::quiet_NaN();
      dropped += static_cast<double>(len);
    }
  };
  drop({"speed"}, 5.0, 60.0);
  drop({"temperature", "salinity", "conductivity"}, 2.0, 20.0);
  drop({"pitch", "roll"}, 1.0, 5.0);
}

}  // namespace auv::sim
