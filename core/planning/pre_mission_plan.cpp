#include "planning/pre_mission_plan.h"

#include "planning/planning_messages.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "ballast/ballast_solver.h"
#include "ballast/mass_quanta.h"
#include "ballast/solution_text.h"
#include "common/input_error.h"
#include "common/units.h"
#include "firstmission/hugin_first_mission.h"
#include "planning/change_explanation.h"
#include "planning/flight_pitch.h"
#include "vehicle/installed_check.h"

namespace auv {
namespace {

using ballast::toKg;
using ballast::toQuanta;

std::vector<double> usableSizes(const VehicleProfile& v, bool optional) {
  std::vector<double> s = v.kit.pieces_kg;
  if (optional) s.insert(s.end(), v.kit.optional_pieces_kg.begin(), v.kit.optional_pieces_kg.end());
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

// The finest step between the totals the kit can add or remove: the
// greatest common divisor of the piece sizes.
double totalStepKg(const std::vector<double>& sizes) {
  std::int64_t g = 0;
  for (double s : sizes) g = std::gcd(g, toQuanta(s));
  return g > 0 ? toKg(g) : sizes.front();
}

std::string roleOf(const PlannedWater& w, const PlannedWater& operating) {
  if (w.depth_m == 0.0) return "surface";
  if (w.depth_m > operating.depth_m) return "deepest";
  return "transit";
}

// Thesis order FS, FP, AS, AP as profile indices (two fore, two aft, each
// pair one starboard and one port); InputError otherwise.
std::array<std::size_t, 4> thesisCorners(const std::vector<AdjustmentPoint>& pts) {
  const InputError bad("policy", "the classic table needs four points: two fore, two aft, each pair one starboard "
                       "and one port", "use --policy exact or half for this vehicle");
  if (pts.size() != 4) throw bad;
  std::array<std::size_t, 4> idx{0, 1, 2, 3};
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return pts[a].position_m.x() > pts[b].position_m.x(); });
  if (!(pts[idx[1]].position_m.x() > pts[idx[2]].position_m.x())) throw bad;
  for (std::size_t k : {0u, 2u}) {
    if (pts[idx[k]].position_m.y() < pts[idx[k + 1]].position_m.y()) std::swap(idx[k], idx[k + 1]);
    if (!(pts[idx[k]].position_m.y() > pts[idx[k + 1]].position_m.y())) throw bad;
  }
  return idx;
}

// Pieces that take a point from `from_kg` to `to_kg`: add the difference
// largest piece first, or take out installed pieces; if the installed pieces
// cannot make the difference, swap to the fewest pieces for the new total.
std::vector<int> moveToTotal(const std::vector<int>& have, const std::vector<double>& sizes, double from_kg,
                             double to_kg, const std::string& point_name) {
  std::vector<int> d(sizes.size(), 0);
  std::int64_t rest = toQuanta(to_kg) - toQuanta(from_kg);
  if (rest == 0) return d;
  const bool add = rest > 0;
  rest = std::abs(rest);
  for (std::size_t s = sizes.size(); s-- > 0;) {
    const std::int64_t q = toQuanta(sizes[s]);
    std::int64_t n = rest / q;
    if (!add) n = std::min<std::int64_t>(n, s < have.size() ? have[s] : 0);
    d[s] = static_cast<int>(add ? n : -n);
    rest -= n * q;
  }
  if (rest == 0) return d;
  const std::vector<int> target = decomposeInstalled(to_kg, sizes, point_name);
  for (std::size_t s = 0; s < sizes.size(); ++s) d[s] = target[s] - (s < have.size() ? have[s] : 0);
  return d;
}

void fillPoints(const BallastProblem& pr, const std::vector<std::vector<int>>& delta, PreMissionPlan& out) {
  out.points.clear();
  for (std::size_t p = 0; p < pr.points.size(); ++p) {
    PointRecommendation r;
    r.name = pr.points[p].name;
    r.label = pr.points[p].label;
    for (std::size_t s = 0; s < pr.piece_sizes_kg.size(); ++s) {
      r.add_kg += delta[p][s] * pr.piece_sizes_kg[s];
      if (delta[p][s] != 0) r.pieces.push_back({pr.piece_sizes_kg[s], delta[p][s]});
    }
    r.add_kg = toKg(toQuanta(r.add_kg));
    out.points.push_back(r);
  }
}

// 1-sigma of the predicted attitude from the estimate's sigmas, each
// propagated by central differences through the exact static trim.
void attitudeSigmas(const BallastProblem& pr, const std::vector<std::vector<int>>& delta, const EstimatedVehicle& ev,
                    const TrimEstimate& e, PreMissionPlan& out) {
  auto with = [&](double dm, const Eigen::Vector3d& dr) {
    BallastProblem q = pr;
    q.vehicle.mass_kg = ev.mass.mass_kg + dm;
    q.vehicle.cg_m = ev.mass.cg_m + dr;
    q.vehicle.moment_kgm = q.vehicle.mass_kg * q.vehicle.cg_m;
    return evaluateMove(q, delta);
  };
  double vp = 0.0, vr = 0.0;
  auto add = [&](double dm, const Eigen::Vector3d& dr) {
    if (dm == 0.0 && dr.isZero()) return;
    const BallastSolution a = with(dm, dr), b = with(-dm, -dr);
    vp += std::pow(0.5 * (a.pitch_deg - b.pitch_deg), 2);
    vr += std::pow(0.5 * (a.roll_deg - b.roll_deg), 2);
  };
  add(ev.mass_sigma_kg, Eigen::Vector3d::Zero());
  add(0.0, Eigen::Vector3d(e.cg_x_sigma_m, 0, 0));
  add(0.0, Eigen::Vector3d(0, e.cg_y_sigma_m, 0));
  out.pitch_sigma_deg = std::sqrt(vp);
  out.roll_sigma_deg = std::sqrt(vr);
}

// The pitch the vehicle flies at the last mission's cruise speed, before
// and after the move, at the operating point.
void predictFlightPitch(const VehicleProfile& v, const TrimEstimate& e, const EstimatedVehicle& ev,
                        const BallastSolution& sol, PreMissionPlan& out) {
  const PlannedPointResult& op = out.at_points.front();
  out.flight_pitch_before_deg =
      flightPitchDeg(v, e.cruise_speed_mps, ev.mass.mass_kg, ev.mass.cg_m, op, e.calibrated_hydrodynamics);
  double added = 0.0;
  for (const auto& p : out.points) added += p.add_kg;
  out.flight_pitch_after_deg =
      flightPitchDeg(v, e.cruise_speed_mps, ev.mass.mass_kg + added, sol.cg_m, op, e.calibrated_hydrodynamics);
  if (!out.flight_pitch_after_deg) return;
  out.flight_speed_mps = e.cruise_speed_mps;
  out.flight_pitch_in_band = std::abs(*out.flight_pitch_after_deg) <= v.spec.pitch_tolerance_deg;
  // The solver's pitch warnings are about the attitude at rest; say so, and
  // what the vehicle will fly, which is what the band is about.
  char buf[160];
  std::snprintf(buf, sizeof buf, " (at rest); flying level at %.1f m/s it pitches %+.2f\u00b0, %s", e.cruise_speed_mps,
                *out.flight_pitch_after_deg, *out.flight_pitch_in_band ? "inside the band" : "outside the band");
  char speed[32], pitch[32];
  std::snprintf(speed, sizeof speed, "%.1f", e.cruise_speed_mps);
  std::snprintf(pitch, sizeof pitch, "%+.2f", *out.flight_pitch_after_deg);
  for (Message& w : out.warnings) {
    if (w.rfind("pitch band", 0) != 0) continue;
    std::string english = w;
    const std::size_t semi = english.find(';');
    english.insert(semi == std::string::npos ? english.size() : semi, buf);
    std::vector<std::string> args = w.args();
    args.insert(args.end(), {speed, pitch, *out.flight_pitch_in_band ? "inside" : "outside"});
    w = Message(w.id(), english, args);
  }
}

std::vector<std::vector<int>> classicMove(const VehicleProfile& v, const PreMissionInput& in, const BallastProblem& pr,
                                          PreMissionPlan& out) {
  const std::array<std::size_t, 4> at = thesisCorners(v.points);
  const TrimEstimate& e = in.estimate;
  if (!e.depth_error_m) throw InputError("errors.depth_m", "the classic table needs the depth deviation", "give an analysis report with errors");
  if (!e.pitch_error_deg) throw InputError("errors.pitch_deg", "the classic table needs the pitch deviation", "give an analysis report with errors");
  if (!e.roll_deg) throw InputError("errors.roll_deg", "the classic table needs the roll deviation", "give an analysis report with errors");
  ClassicInput c;
  for (std::size_t k = 0; k < 4; ++k) c.installed_kg[k] = in.installed_kg.empty() ? 0.0 : in.installed_kg[at[k]];
  c.depth_error_m = *e.depth_error_m;
  c.pitch_error_deg = *e.pitch_error_deg;
  c.roll_deg = *e.roll_deg;
  c.computed_imbalance_kg = in.classic_computed_imbalance_kg;
  c.x_fore_m = v.points[at[0]].position_m.x();
  c.x_aft_m = v.points[at[2]].position_m.x();
  c.small_piece_kg = pr.piece_sizes_kg.front();
  c.piece_sizes_kg = pr.piece_sizes_kg;
  c.thresholds.depth_lo_m = 0.0;
  c.thresholds.depth_hi_m = 0.1;
  c.thresholds.pitch_deg = v.spec.pitch_tolerance_deg;
  c.thresholds.roll_deg = v.spec.roll_tolerance_deg;
  c.thresholds.weight_kg = v.spec.net_buoyancy_max_kg;
  const ClassicResult r = classicAdjustment(c);
  std::vector<std::vector<int>> delta(v.points.size(), std::vector<int>(pr.piece_sizes_kg.size(), 0));
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t p = at[k];
    const std::vector<int> have = pr.installed.empty() ? std::vector<int>{} : pr.installed[p];
    delta[p] = moveToTotal(have, pr.piece_sizes_kg, c.installed_kg[k], r.mapped_kg[k], v.points[p].name);
  }
  out.details["classic"] = {{"weight_case", r.weight_case}, {"pitch_error_sign", r.pitch_sign},
                            {"roll_error_sign", r.roll_sign}, {"blocked", r.blocked},
                            {"deviations", {{"depth_m", c.depth_error_m}, {"pitch_deg", c.pitch_error_deg},
                                            {"roll_deg", c.roll_deg}}}};
  out.notes.push_back(
      Message(planning::msg::kClassicTable, {r.weight_case, r.pitch_sign, r.roll_sign, ballast::sizeText(c.small_piece_kg)}));
  if (r.blocked) out.warnings.push_back(Message(planning::msg::kClassicBlocked));
  if (in.use_optional_pieces) out.notes.push_back(Message(planning::msg::kClassicStandardKit));
  return delta;
}

}  // namespace

const char* toString(PlanPolicy p) {
  switch (p) {
    case PlanPolicy::Exact: return "exact";
    case PlanPolicy::HalfWay: return "half";
    case PlanPolicy::Classic: return "classic";
  }
  return "exact";
}

PlanPolicy planPolicyFromString(const std::string& s) {
  if (s == "exact") return PlanPolicy::Exact;
  if (s == "half") return PlanPolicy::HalfWay;
  if (s == "classic") return PlanPolicy::Classic;
  throw InputError("policy", "unknown policy '" + s + "'", "use exact, half or classic");
}

namespace {

// What the analysed log did not fly as commanded, in words; empty when it did.
std::string notAsCommanded(const TrimEstimate& e) {
  std::string s;
  auto add = [&](bool on, const char* what) {
    if (on) s += (s.empty() ? "" : ", ") + std::string(what);
  };
  add(e.log_too_light, "too light or stern-heavy to hold its depth");
  add(e.log_too_heavy, "too heavy or bow-heavy to hold its depth");
  add(e.log_porpoising, "porpoising");
  return s;
}

}  // namespace

PreMissionPlan planPreMission(const VehicleProfile& v, const PreMissionInput& in) {
  if (v.points.empty()) {
    throw InputError("vehicle", "profile '" + v.id + "' has no adjustment points", "add adjustment_points to the profile");
  }
  if (!in.installed_kg.empty()) checkInstalledKg(v, in.installed_kg, "installed");
  if (!(in.sigma_factor >= 0.0) || !std::isfinite(in.sigma_factor)) {
    throw InputError("sigma_factor", "must be a number >= 0", "use 1.645 for one-sided 95 %");
  }
  HullModel hull = in.hull.value_or(v.hull);
  if (!in.hull) {  // the hull law the analysis fitted, when it replaced the profile's
    hull.compressibility_per_dbar = in.estimate.hull_compressibility_per_dbar.value_or(hull.compressibility_per_dbar);
    hull.thermal_expansion_per_degC = in.estimate.hull_thermal_expansion_per_degC.value_or(hull.thermal_expansion_per_degC);
  }
  PreMissionPlan out;
  out.vehicle_id = v.id;
  out.policy = in.policy;
  out.estimate = in.estimate;
  out.vehicle = estimatedVehicle(v, hull, in.estimate);
  const bool standard_only = in.policy == PlanPolicy::Classic;
  out.piece_sizes_kg = usableSizes(v, in.use_optional_pieces && !standard_only);

  // Planned points: the band applies at the operating point, safety at all.
  std::vector<PlannedWater> waters{in.next.operating};
  waters.insert(waters.end(), in.next.transit.begin(), in.next.transit.end());
  double sigma_water = 0.0, sigma_law = 0.0, b_min = 0.0;
  for (std::size_t i = 0; i < waters.size(); ++i) {
    const ResolvedPoint rp = resolvePoint(hull, waters[i]);
    PlannedPointResult r;
    r.role = i == 0 ? "operating" : roleOf(waters[i], in.next.operating);
    r.water = waters[i];
    r.state = rp.state;
    r.displaced_kg = rp.displaced_kg;
    r.net_before_kg = rp.displaced_kg - out.vehicle.mass.mass_kg;
    out.at_points.push_back(r);
    sigma_water = std::max(sigma_water, displacedSigmaKg(hull, waters[i], in.next.temperature_sigma_degC,
                                                         in.next.salinity_sigma_psu));
    if (!in.hull)  // a fitted hull law carries its own uncertainty to each depth and water
      sigma_law = std::max(sigma_law, hullLawSigmaKg(hull, in.estimate.water, waters[i],
                                                     in.estimate.hull_compressibility_sigma_per_dbar,
                                                     in.estimate.hull_thermal_expansion_sigma_per_degC));
    b_min = i == 0 ? rp.displaced_kg : std::min(b_min, rp.displaced_kg);
  }
  const double b_op = out.at_points.front().displaced_kg;
  out.hull_law_sigma_kg = sigma_law;
  out.net_sigma_kg = std::hypot(in.estimate.net_buoyancy_sigma_kg, sigma_water, sigma_law);
  out.margin_kg = in.sigma_factor * out.net_sigma_kg;
  // The same margin off the top keeps the true value inside the spec band
  // at both ends; where the two margins overlap, safety wins.
  out.band_lo_kg = std::max(v.spec.net_buoyancy_min_kg, out.margin_kg + (b_op - b_min));
  out.band_hi_kg = std::max(v.spec.net_buoyancy_max_kg - out.margin_kg, out.band_lo_kg);

  BallastProblem pr;
  pr.vehicle = out.vehicle.mass;
  pr.displaced_mass_kg = b_op;
  pr.cb_m = v.cb_m;
  pr.points = v.points;
  pr.piece_sizes_kg = out.piece_sizes_kg;
  pr.spec = v.spec;
  pr.spec.net_buoyancy_min_kg = out.band_lo_kg;
  pr.spec.net_buoyancy_max_kg = out.band_hi_kg;
  pr.policy = in.policy == PlanPolicy::HalfWay ? BallastPolicy::HalfWay : BallastPolicy::Exact;
  for (std::size_t i = 0; i < in.installed_kg.size(); ++i) {
    pr.installed.push_back(decomposeInstalled(in.installed_kg[i], pr.piece_sizes_kg, v.points[i].name));
  }

  const BallastSolution now = evaluateMove(pr, std::vector<std::vector<int>>(
                                                   v.points.size(), std::vector<int>(pr.piece_sizes_kg.size(), 0)));
  out.net_before_kg = now.net_buoyancy_kg;
  out.pitch_before_deg = now.pitch_deg;
  out.roll_before_deg = now.roll_deg;

  BallastSolution sol;
  if (in.policy == PlanPolicy::Classic) {
    out.delta = classicMove(v, in, pr, out);
    sol = evaluateMove(pr, out.delta);
  } else {
    // Level flight at zero pitch needs W x_G = l (B - W) (planes carry the
    // net buoyancy, the hull no lift): with the calibrated model the solver
    // aims the CG there rather than over the CB, so the vehicle flies level
    // at every speed (thesis §5.3.2 judges pitch in flight).
    std::optional<double> lever_m;
    if (in.estimate.calibrated_hydrodynamics) lever_m = planeLeverM(v, in.estimate.calibrated_hydrodynamics);
    const double band_hi0 = pr.spec.net_buoyancy_max_kg;
    // The level-flight CG moves with the net buoyancy the move ends at
    // (l dB / W: about 1 deg of pitch per 0.2 kg on HUGIN), which the kit's
    // pieces decide: aim at the band centre, then again at the net the
    // solver reached until the two agree.
    double net_aim = 0.5 * (out.band_lo_kg + out.band_hi_kg);
    for (int aim = 0; aim < 3; ++aim) {
      pr.spec.net_buoyancy_max_kg = band_hi0;
      if (lever_m) {
        // The mass after the move is not known before solving; a few kg in
        // 1500 change x by < 0.5 %.
        pr.cb_m.x() = v.cb_m.x() + *lever_m * net_aim / out.vehicle.mass.mass_kg;
        out.details["flight_level_cg_x_mm"] = units::mToMm(pr.cb_m.x() - v.cb_m.x());
      }
      // No kit total inside [lo, hi]: the solver would take the nearest, which
      // may lie under the safety margin. Widen the band upward by the finest
      // step the kit's totals have (0.1 kg for 0.5 and 1.2 kg pieces), so the
      // answer stays as close above the margin as the kit allows, until it is
      // safe or the band has grown by eight smallest pieces.
      const double step_kg = totalStepKg(pr.piece_sizes_kg);
      const double widen_max_kg = 8.0 * pr.piece_sizes_kg.front();
      for (double widened = 0.0;; widened += step_kg) {
        sol = solveBallast(pr);
        if (sol.net_buoyancy_kg >= out.band_lo_kg - 1e-6 || widened >= widen_max_kg - 1e-9) break;
        pr.spec.net_buoyancy_max_kg += step_kg;
      }
      if (!lever_m || std::abs(sol.net_buoyancy_kg - net_aim) < 0.02) break;
      net_aim = sol.net_buoyancy_kg;
    }
    out.band_hi_kg = pr.spec.net_buoyancy_max_kg;
    out.delta = sol.delta;
    out.notes.assign(sol.notes.begin(), sol.notes.end());
    out.warnings.assign(sol.warnings.begin(), sol.warnings.end());
  }
  if (pr.cb_m.x() != v.cb_m.x()) {
    // Report the attitude at rest about the real CB.
    pr.cb_m = v.cb_m;
    sol = evaluateMove(pr, out.delta);
  }
  fillPoints(pr, out.delta, out);
  out.predicted.net_buoyancy_kg = sol.net_buoyancy_kg;
  out.predicted.cg_offset_m = (sol.cg_m - v.cb_m).head<2>();
  out.predicted.pitch_deg = sol.pitch_deg;
  out.predicted.roll_deg = sol.roll_deg;
  attitudeSigmas(pr, out.delta, out.vehicle, in.estimate, out);

  // The spec's band, judged at the operating point (not the widened one).
  const TrimSpec& spec = v.spec;
  out.buoyancy_in_band = sol.net_buoyancy_kg >= std::max(0.0, spec.net_buoyancy_min_kg) - 1e-6 &&
                         sol.net_buoyancy_kg <= spec.net_buoyancy_max_kg + 1e-6;
  out.pitch_in_band = sol.pitch_in_band;
  out.roll_in_band = sol.roll_in_band;

  double added = 0.0;
  for (const auto& p : out.points) added += p.add_kg;
  out.safe = true;
  for (auto& r : out.at_points) {
    r.net_after_kg = r.displaced_kg - out.vehicle.mass.mass_kg - added;
    if (r.net_after_kg < out.margin_kg - 1e-6) out.safe = false;
  }
  predictFlightPitch(v, in.estimate, out.vehicle, sol, out);
  // Too wide for the band: the margin alone takes half of it, or the
  // answer ends outside it. Then ask for the manoeuvre.
  const double band_kg = spec.net_buoyancy_max_kg - spec.net_buoyancy_min_kg;
  const bool too_wide = in.policy != PlanPolicy::Classic && (!out.buoyancy_in_band || 2.0 * out.margin_kg > band_kg);
  auto num = [](const char* f, double x) {
    char b[32];
    std::snprintf(b, sizeof b, f, x);
    return std::string(b);
  };
  if (too_wide && in.estimate.calibration_manoeuvre) {
    out.calibration_manoeuvre = in.estimate.calibration_manoeuvre;
    const nlohmann::json& m = *out.calibration_manoeuvre;
    out.notes.push_back(Message(planning::msg::kManoeuvre, {num("%.2f", out.net_sigma_kg), num("%.1f", band_kg),
                                                  std::to_string(m["legs"].size()),
                                                  num("%.2f", m["expected_sigma"]["net_buoyancy_kg"].get<double>())}));
  }
  // The move itself calibrates the next mission's analysis (with this log
  // as history); say how far, and whether that alone will do.
  if (too_wide && in.estimate.after_move_net_sigma_kg) {
    out.after_move_net_sigma_kg = in.estimate.after_move_net_sigma_kg;
    out.after_move_x_sigma_m = in.estimate.after_move_x_sigma_m;
    const double s_after = *out.after_move_net_sigma_kg;
    const bool enough = 2.0 * in.sigma_factor * s_after <= band_kg;  // the same test as too_wide
    out.notes.push_back(Message(enough ? planning::msg::kAfterMove : planning::msg::kAfterMoveStillWide,
                                {num("%.2f", s_after),
                                 out.after_move_x_sigma_m
                                     ? num(*out.after_move_x_sigma_m < 1e-4 ? "%.2f" : "%.1f", *out.after_move_x_sigma_m * 1e3)
                                     : "?"}));
  }
  explainPlan(v, pr, out);
  if (const std::string off = notAsCommanded(in.estimate); !off.empty())
    out.notes.push_back(Message(planning::msg::kLogNotAsCommanded, {off, num("%.2f", out.net_sigma_kg)}));
  if (in.estimate.cg_y_basis == "cruise" && in.estimate.cg_y_m) {
    char rpm[32];
    std::snprintf(rpm, sizeof rpm, "%.0f", in.estimate.cruise_rpm);
    out.notes.push_back(Message(planning::msg::kRollAtCruise, {rpm}));
  }
  return out;
}

}  // namespace auv
