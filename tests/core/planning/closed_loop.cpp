#include "closed_loop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "common/units.h"
#include "hydrostatics/static_trim.h"
#include "planning/estimated_vehicle.h"

namespace auv::closed_loop {
namespace {

// Platform-independent draws (the standard distributions are not).
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double gauss(std::mt19937_64& rng) {
  const double u1 = (static_cast<double>(rng() >> 11) + 1.0) * 0x1.0p-53;
  const double u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}
double between(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }
double randomSign(std::mt19937_64& rng) { return uniform01(rng) < 0.5 ? -1.0 : 1.0; }

PlannedWater randomWater(std::mt19937_64& rng) {
  PlannedWater w;
  w.temperature_degC = between(rng, 4.0, 14.0);
  w.salinity_psu = between(rng, 33.0, 35.5);
  w.depth_m = between(rng, 20.0, 100.0);
  return w;
}

// The thesis's spec pairs a depth error of 0..+0.1 m with 0..+1.2 kg of net
// buoyancy (§5.1 item 7): the analytic truth maps one onto the other.
double depthErrorOf(double net_kg) { return 0.1 * net_kg / 1.2; }

}  // namespace

std::vector<LoopCase> makeCases(const VehicleProfile& v, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<LoopCase> cases;
  for (int i = 0; i < count; ++i) {
    LoopCase c;
    c.light_kg = between(rng, 1.0, 8.0);
    c.x_mm = randomSign(rng) * between(rng, 5.0, 25.0);
    c.y_mm = randomSign(rng) * between(rng, 0.5, 3.0);
    c.water1 = randomWater(rng);
    c.water2 = randomWater(rng);
    for (std::size_t p = 0; p < v.points.size(); ++p) {
      c.installed_kg.push_back(1.2 * std::round(between(rng, 9.6, 24.0) / 1.2));
    }
    c.seed = rng();
    cases.push_back(c);
  }
  return cases;
}

Harness::Harness(VehicleProfile v, AnalysisNoise noise) : v_(std::move(v)), noise_(noise) {}

Truth Harness::truthOf(const LoopCase& c) const {
  Truth t;
  const ResolvedPoint p = resolvePoint(v_.hull, c.water1);
  t.mass_kg = p.displaced_kg - c.light_kg;
  t.cg_m = v_.cb_m + Eigen::Vector3d(units::mmToM(c.x_mm), units::mmToM(c.y_mm), v_.bg_m);
  t.installed_kg = c.installed_kg;
  return t;
}

MissionResult Harness::fly(const Truth& t, const PlannedWater& w) const {
  const ResolvedPoint op = resolvePoint(v_.hull, w);
  PlannedWater surface = w;
  surface.depth_m = 0.0;
  const ResolvedPoint sf = resolvePoint(v_.hull, surface);
  MissionResult m;
  m.net_kg = op.displaced_kg - t.mass_kg;
  m.min_net_kg = std::min(m.net_kg, sf.displaced_kg - t.mass_kg);
  const double W = units::g0 * t.mass_kg, B = units::g0 * op.displaced_kg;
  const StaticTrim st = staticTrim(W, B, t.cg_m, v_.cb_m);
  m.static_pitch_deg = units::radToDeg(st.pitch_rad);
  m.static_roll_deg = units::radToDeg(st.roll_rad);
  m.depth_error_m = depthErrorOf(m.net_kg);

  return m;
}

TrimEstimate Harness::analyse(const Truth& t, const PlannedWater& w, std::mt19937_64& rng) const {
  const ResolvedPoint op = resolvePoint(v_.hull, w);
  const MissionResult m = fly(t, w);
  const double x_mm = units::mToMm(t.cg_m.x() - v_.cb_m.x()), y_mm = units::mToMm(t.cg_m.y() - v_.cb_m.y());
  const double s_net = noise_.net_a_kg + noise_.net_b * std::abs(m.net_kg);
  const double s_x = noise_.x_a_mm + noise_.x_b * std::abs(x_mm);
  const double s_y = noise_.y_a_mm + noise_.y_b * std::abs(y_mm);
  TrimEstimate e;
  e.net_buoyancy_kg = m.net_kg + noise_.realised * s_net * gauss(rng);
  e.net_buoyancy_sigma_kg = s_net;
  e.cg_x_m = units::mmToM(x_mm + noise_.realised * s_x * gauss(rng));
  e.cg_x_sigma_m = units::mmToM(s_x);
  e.cg_y_m = units::mmToM(y_mm + noise_.realised * s_y * gauss(rng));
  e.cg_y_sigma_m = units::mmToM(s_y);
  e.water = op.state;
  e.salinity_psu = w.salinity_psu;
  e.depth_m = w.depth_m;
  e.depth_error_m = m.depth_error_m + noise_.depth_sensor_sigma_m * gauss(rng);
  e.pitch_error_deg = m.static_pitch_deg + noise_.pitch_sensor_sigma_deg * gauss(rng);
  e.roll_deg = m.static_roll_deg + noise_.roll_sensor_sigma_deg * gauss(rng);
  return e;
}

SpecCheck Harness::judge(const MissionResult& m, double best_roll_deg) const {
  const TrimSpec& s = v_.spec;
  SpecCheck c;
  c.net = m.net_kg >= s.net_buoyancy_min_kg - 1e-9 && m.net_kg <= s.net_buoyancy_max_kg + 1e-9;
  c.depth = m.depth_error_m >= -1e-12 && m.depth_error_m <= 0.1 + 1e-12;
  c.pitch = std::abs(m.static_pitch_deg) <= s.pitch_tolerance_deg;
  c.roll = std::abs(m.static_roll_deg) <= std::max(s.roll_tolerance_deg, std::abs(best_roll_deg) + s.roll_tolerance_deg);
  return c;
}

void Harness::apply(Truth& t, const PreMissionPlan& p) const {
  Eigen::Vector3d moment = t.mass_kg * t.cg_m;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    t.mass_kg += p.points[i].add_kg;
    moment += p.points[i].add_kg * v_.points[i].position_m;
    // Whole 0.1 g, as the pieces are: no 3.6 - 2.4 - 1.2 = -4e-16 kg.
    t.installed_kg[i] = std::round((t.installed_kg[i] + p.points[i].add_kg) * 1e4) / 1e4;
  }
  t.cg_m = moment / t.mass_kg;
}

Harness::Best Harness::best(const Truth& t0, const PlannedWater& w, bool optional_pieces) const {
  Truth t = t0;
  apply(t, perfectPlan(t0, w, optional_pieces));
  const MissionResult m = fly(t, w);
  return {m.static_pitch_deg, m.static_roll_deg};
}

PreMissionPlan Harness::perfectPlan(const Truth& t0, const PlannedWater& w, bool optional_pieces) const {
  TrimEstimate e;
  const ResolvedPoint op = resolvePoint(v_.hull, w);
  e.net_buoyancy_kg = op.displaced_kg - t0.mass_kg;
  e.cg_x_m = t0.cg_m.x() - v_.cb_m.x();
  e.cg_y_m = t0.cg_m.y() - v_.cb_m.y();
  e.water = op.state;
  e.salinity_psu = w.salinity_psu;
  e.depth_m = w.depth_m;
  PreMissionInput in;
  in.installed_kg = t0.installed_kg;
  in.estimate = e;
  in.next = nextMissionWater(w, 0.0, "truth");
  in.next.temperature_sigma_degC = 0.0;
  in.next.salinity_sigma_psu = 0.0;
  in.use_optional_pieces = optional_pieces;
  return planPreMission(v_, in);
}

Outcome Harness::runOnce(const LoopCase& c, PlanPolicy policy, bool optional_pieces, double k) const {
  Truth t = truthOf(c);
  std::mt19937_64 rng(c.seed);
  Outcome o;
  o.before = fly(t, c.water1);
  PreMissionInput in;
  in.installed_kg = t.installed_kg;
  in.estimate = analyse(t, c.water1, rng);
  in.next = nextMissionWater(c.water2, 0.0, "operator");
  in.next.temperature_sigma_degC = noise_.next_temperature_sigma_degC;
  in.next.salinity_sigma_psu = noise_.next_salinity_sigma_psu;
  in.policy = policy;
  in.use_optional_pieces = optional_pieces;
  in.sigma_factor = k;
  const PreMissionPlan p = planPreMission(v_, in);
  const Best b = best(t, c.water2, optional_pieces);
  o.best_roll_deg = b.roll_deg;
  o.best_pitch_deg = b.pitch_deg;
  o.reachable = std::abs(b.pitch_deg) <= v_.spec.pitch_tolerance_deg;
  apply(t, p);
  for (const auto& pt : p.points) o.added_kg += pt.add_kg;
  o.after = fly(t, c.water2);
  o.spec = judge(o.after, o.best_roll_deg);
  o.safe = o.after.min_net_kg >= 0.0;
  o.warnings.assign(p.warnings.begin(), p.warnings.end());
  return o;
}

std::optional<int> Harness::classicMissions(const LoopCase& c, int max_missions) const {
  Truth t = truthOf(c);
  std::mt19937_64 rng(c.seed);
  const double best = this->best(t, c.water2, false).roll_deg;
  PlannedWater w = c.water1;
  for (int k = 0; k <= max_missions; ++k) {
    if (std::getenv("LOOP_TRACE")) {
      const MissionResult m = fly(t, w);
      const SpecCheck j = judge(m, best);
      std::fprintf(stderr, "  mission %d: net %+.2f pitch %+.2f roll %+.2f (best %.2f) ok %d%d%d%d\n", k,
                   m.net_kg, m.static_pitch_deg, m.static_roll_deg, best, j.net, j.pitch, j.depth, j.roll);
    }
    if (judge(fly(t, w), best).all()) return k;
    if (k == max_missions) break;
    PreMissionInput in;
    in.installed_kg = t.installed_kg;
    in.estimate = analyse(t, w, rng);
    in.next = nextMissionWater(c.water2, 0.0, "operator");
    in.policy = PlanPolicy::Classic;
    w = c.water2;
    apply(t, planPreMission(v_, in));
  }
  return std::nullopt;
}

}  // namespace auv::closed_loop
