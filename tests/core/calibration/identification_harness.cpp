#include "identification_harness.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <random>

#include "missionlog/interchange_csv.h"

#include "analysis/analysis_report.h"
#include "analysis/mission_analysis.h"
#include "common/units.h"
#include "discrepancy/synthetic_auv.h"
#include "planning/next_mission_water.h"
#include "planning/pre_mission_plan.h"
#include "planning/trim_estimate.h"
#include "sim/flown_mass.h"
#include "sim/sim_log.h"
#include "sim/simulator.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"

namespace auv::identification {
namespace {

const std::string kResources = AUV_RESOURCE_DIR;

nlohmann::json nominalCompanion() { return JsonReader::parseFile(kResources + "/sim/hugin1000_hydrodynamics.json"); }

// The profile with a companion's sections, as the catalog merges them
// (vehicle_catalog.cpp), autopilot included.
VehicleProfile profileWith(const nlohmann::json& companion) {
  VehicleProfile p = loadVehicleProfile(kResources + "/vehicles/hugin1000.json");
  for (const char* k : {"hydrodynamics", "actuators", "sim_assumptions", "autopilot"}) p.sections[k] = companion[k];
  return p;
}

const std::vector<double> kInstalled = {7.2, 7.2, 25.2, 25.2};

struct Flown {
  MissionLog log;
  double mass_kg = 0.0, cg_x_m = 0.0, cg_y_m = 0.0, bg_m = 0.0;
  double min_net_kg = 0.0, mean_net_kg = 0.0;
};

Flown fly(const sim::VehicleModel& truth, const sim::DepthAutopilotConfig& ap, const sim::SurveyMission& m,
          const std::vector<MassItem>& installed, const sim::BallastError& err, std::uint64_t noise_seed,
          const std::vector<double>& installed_kg, const discrepancy::SyntheticAuvTruth& effect) {
  sim::Scenario sc = m.scenario;
  sc.extra_masses = installed;
  sc.ballast_error = err;
  discrepancy::applyTruthEffects(sc, effect, sim::scenarioDuration(sc));
  sim::SimOptions opt = m.options;
  opt.seed = noise_seed;
  const sim::WaterColumn water = m.water();
  const sim::SimTrace tr = sim::simulate(truth, ap, water, sc, opt);
  Flown f;
  f.log = sim::toMissionLog(tr, {"hugin1000", "plan", "identification harness", noise_seed, 0, installed_kg, {sim::latitudeMetadata(m.latitude_deg)}});
  sim::applyDropouts(f.log, noise_seed);
  discrepancy::recordSensorBiases(f.log, effect);
  f.mass_kg = tr.truth.mass_kg;
  f.cg_x_m = tr.truth.cg_x_m;
  f.cg_y_m = tr.truth.cg_y_m;
  f.bg_m = tr.truth.cg_z_m;
  double s = 0.0, mn = 1e30;
  for (double n : tr.net_buoyancy_n) s += n, mn = std::min(mn, n);
  f.mean_net_kg = s / static_cast<double>(tr.net_buoyancy_n.size()) / units::g0;
  f.min_net_kg = mn / units::g0;
  return f;
}

analysis::AnalysisReport analyse(const Flown& f, const VehicleProfile& p, const std::vector<double>& installed,
                                 bool transients, double pitch_alignment_sigma_deg,
                                 std::optional<double> coefficient_rel_sigma) {
  analysis::AnalysisOptions a;
  a.coefficient_rel_sigma = coefficient_rel_sigma;
  a.use_transients = transients;
  a.pitch_alignment_sigma_deg = pitch_alignment_sigma_deg;
  a.log_name = "identification";
  a.installed_kg = installed;
  a.bg_m = f.bg_m;  // a roll test measures BG of the vehicle as it is
  return analysis::analyzeMission(f.log, p, a);
}

// Pitch at steady depth at the cruise propeller speed (the highest rpm of
// the level segments used), duration-weighted: the speed the survey flies and
// the planner predicts its flight pitch at. All level segments without rpm.
// The pitch at cruise: the steady segments at the fastest survey speed
// (not above survey_top_rpm, so a manoeuvre's faster leg does not count).
double cruisePitchDeg(const analysis::AnalysisReport& rp, double survey_top_rpm) {
  double top = -1e30;
  for (const auto& s : rp.segments)
    if (s.used && std::isfinite(s.pitch_deg) && std::isfinite(s.prop_rpm) && s.prop_rpm < survey_top_rpm + 5.0)
      top = std::max(top, s.prop_rpm);
  double sw = 0.0, sp = 0.0;
  for (const auto& s : rp.segments) {
    if (!s.used || !std::isfinite(s.pitch_deg) || s.kind != analysis::SegmentKind::kSteady) continue;
    if (top > -1e30 && !(std::abs(s.prop_rpm - top) < 5.0)) continue;
    const double w = s.end_s - s.start_s;
    sw += w;
    sp += w * s.pitch_deg;
  }
  return sw > 0.0 ? sp / sw : rp.pitch_at_steady_depth_deg.mean;
}

// The calibration manoeuvre a plan asked for, appended to the mission as
// the vehicle's own legs: level legs at the operating depth, and depth
// changes as a depth command ramped at the asked rate (one ramp leg: a
// staircase of 1-s legs would step the command on every sample of the 1 Hz
// log, and the samples would catch the autopilot's kick at one phase).
bool appendManoeuvre(const nlohmann::json& manoeuvre, double op_depth_m, sim::SurveyMission& m) {
  if (!manoeuvre.contains("flight") || !manoeuvre["flight"].is_array()) return false;
  double depth = op_depth_m;
  bool any = false;
  for (const auto& l : manoeuvre["flight"]) {
    const double rpm = l.at("prop_rpm").get<double>(), rate = l.at("depth_rate_mps").get<double>();
    const double seconds = l.at("duration_s").get<double>();
    sim::DepthLeg leg;
    leg.prop_demand = rpm;
    if (rate == 0.0) {
      leg.duration_s = seconds;
      leg.depth_m = depth;
      m.scenario.legs.push_back(leg);
    } else {
      depth += rate * seconds;
      leg.duration_s = seconds;
      leg.depth_m = depth;
      leg.ramp = true;
      m.scenario.legs.push_back(leg);
    }
    any = true;
  }
  // Settle back on the operating depth before the log ends.
  if (any) m.scenario.legs.push_back({120.0, op_depth_m, m.rpms.back(), 0.0});
  return any;
}

}  // namespace

Harness::Harness()
    : profile_(profileWith(nominalCompanion())),
      nominal_(sim::loadSimVehicle(loadVehicleProfile(kResources + "/vehicles/hugin1000.json"), kResources)) {}

CaseResult Harness::run(std::uint64_t seed, bool closed_loop, const std::string& dump_prefix) const {
  CaseResult r;
  r.truth = sim::drawTruth(seed);
  sim::SurveyRanges ranges;
  ranges.trace_interval_s = log_interval_s;
  const sim::SurveyMission m = sim::makeSurveyMission(seed, ranges);
  r.speeds = static_cast<int>(m.rpms.size());
  r.depths = static_cast<int>(m.depths_m.size());
  // With a level check, this truth's sensor sits anywhere within the
  // checked tolerance, and the analysis is told that tolerance as its prior.
  discrepancy::SyntheticAuvTruth effects = concealed;
  double alignment_sigma_deg = pitch_alignment_sigma_deg;
  if (level_check_deg > 0.0) {
    std::mt19937_64 rng(seed ^ 0x5eed1e7e1ULL);
    effects.pitch_bias_deg = std::uniform_real_distribution<double>(-level_check_deg, level_check_deg)(rng);
    alignment_sigma_deg = level_check_deg;
  }
  r.pitch_bias_deg = effects.pitch_bias_deg;
  // The diagnostic: the analysis told the truth's own hydrodynamics.
  const bool told_truth = analysis_knows_truth_rel_sigma > 0.0;
  const VehicleProfile told = told_truth ? profileWith(sim::truthHydrodynamicsDoc(nominalCompanion(), r.truth)) : profile_;
  const std::optional<double> coefficient_sigma =
      told_truth ? std::optional<double>(analysis_knows_truth_rel_sigma) : std::nullopt;
  sim::VehicleModel truth = sim::truthModel(nominal_.model, r.truth);
  discrepancy::applyTruthEffects(truth, effects);
  const std::vector<MassItem> installed = sim::installedWeights(profile_, kInstalled);
  // The drawn net buoyancy holds at the start of the mission.
  const sim::WaterSample w0 = m.water().at(m.scenario.initial_depth_m, 0.0);
  const double displaced0 = w0.density_kgm3 * truth.body.hull.volumeAt(w0.temperature_degC, w0.pressure_dbar);
  const sim::BallastError err = sim::truthBallastError(truth, installed, displaced0, r.truth);
  const Flown f = fly(truth, nominal_.autopilot, m, installed, err, seed * 7 + 1, kInstalled, effects);

  const auto t0 = std::chrono::steady_clock::now();
  const analysis::AnalysisReport rep = analyse(f, told, kInstalled, use_transients, alignment_sigma_deg, coefficient_sigma);
  r.analysis_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Through the JSON contract, so the harness also measures code from before the calibration.
  const nlohmann::json rj = analysis::toJson(rep);
  if (!dump_prefix.empty()) {
    writeInterchangeCsv(f.log, dump_prefix + ".csv");
    std::ofstream(dump_prefix + ".json") << rj.dump(1) << "\n";
  }
  if (const auto& d = rj["details"]; d.contains("auv_estimate") && d["auv_estimate"].contains("after_move_expected_sigma"))
  {
    r.after_move_expected_sigma_kg = d["auv_estimate"]["after_move_expected_sigma"]["net_buoyancy_kg"].get<double>();
    r.after_move_expected_x_sigma_mm = d["auv_estimate"]["after_move_expected_sigma"]["cg_x_mm"].get<double>();
  }
  if (const auto& d = rj["details"]; d.contains("flight_envelope")) {
    r.too_light = d["flight_envelope"].contains("too_light");
    r.too_heavy = d["flight_envelope"].contains("too_heavy");
    r.porpoising = d["flight_envelope"].contains("porpoising");
  }
  if (rj.contains("calibration"))
    for (const auto& q : rj["calibration"]) {
      analysis::CalibrationParameter c;
      c.id = q["id"].get<std::string>();
      c.identified = q["identified"].get<bool>();
      c.used = q.value("used", true);
      if (q["value"].is_number()) c.value = q["value"].get<double>();
      if (q["sigma"].is_number()) c.sigma = q["sigma"].get<double>();
      r.calibration.push_back(c);
    }

  // Truth at the report's reference water: rho V(T, p) - m.
  const double Vref = profile_.hull.volumeAt(rep.temperature_degC.mean, rep.pressure_dbar.mean);
  const double net_truth = rep.density_kgm3.mean * Vref - f.mass_kg;
  r.known = rep.net_buoyancy_kg.known && rep.cg_x_mm.known;
  if (on_first_log) on_first_log(f.log, rep, net_truth, units::mToMm(f.cg_x_m));
  if (r.known) {
    r.net_err_kg = rep.net_buoyancy_kg.value - net_truth;
    r.net_sigma_kg = rep.net_buoyancy_kg.sigma;
    r.x_err_mm = rep.cg_x_mm.value - units::mToMm(f.cg_x_m);
    r.x_sigma_mm = rep.cg_x_mm.sigma;
  }
  r.y_known = rep.cg_y_mm.known;
  if (r.y_known) {
    r.y_err_mm = rep.cg_y_mm.value - units::mToMm(f.cg_y_m);
    r.y_sigma_mm = rep.cg_y_mm.sigma;
  }
  for (const auto& s2 : rep.segments)
    if (s2.used && std::isfinite(s2.prop_rpm)) {
      bool seen = false;
      for (double q : r.log_rpms) seen = seen || std::abs(q - s2.prop_rpm) < 5.0;
      if (!seen) r.log_rpms.push_back(s2.prop_rpm);
    }
  if (!closed_loop || !r.known) return r;

  // The next missions: the same survey lines at one operating depth (the
  // middle of the surveyed depths), in the same stratified water; the
  // operator gives that depth's water from a CTD cast.
  sim::SurveyMission m2 = m;
  const double op_depth = m.depths_m[m.depths_m.size() / 2];
  for (auto& leg : m2.scenario.legs) leg.depth_m = op_depth;
  m2.scenario.initial_depth_m = op_depth;
  const sim::WaterSample wop = m.water().at(op_depth);
  const PlannedWater next{wop.temperature_degC, wop.salinity_psu, op_depth, 60.0};
  auto planFrom = [&](const nlohmann::json& report, const std::vector<double>& installed_now) {
    PreMissionInput in;
    in.installed_kg = installed_now;
    in.estimate = trimEstimateFromReport(report, "identification harness");
    in.next = nextMissionWater(next, op_depth, "operator");
    in.sigma_factor = sigma_factor;
    in.next.temperature_sigma_degC = 0.1;  // a CTD cast before launch
    in.next.salinity_sigma_psu = 0.05;
    in.policy = PlanPolicy::Exact;
    in.use_optional_pieces = true;
    const PreMissionPlan plan = planPreMission(told, in);
    std::vector<double> after = installed_now;
    for (std::size_t i = 0; i < after.size(); ++i)
      after[i] = std::round((after[i] + plan.points[i].add_kg) * 1e4) / 1e4;
    return std::pair{plan, after};
  };
  const TrimSpec& s = profile_.spec;
  const double y_point = std::abs(profile_.points.front().position_m.y() - profile_.cb_m.y());
  // Judged as the thesis does, in flight: the band at the operating point
  // (the planned water), never negative anywhere the mission went, pitch at
  // steady depth, roll at cruise within 0.1 deg of what the kit reaches (the
  // smallest lateral step, the 0.5 kg piece at a side point, moves the roll
  // by atan(0.5 kg |y| / (m BG))).
  // What the kit can reach is not only the smallest lateral step: with the
  // points' capacities (a side point full, the other empty) the best roll
  // with net buoyancy and pitch in band can be degrees. The planner (an
  // exact search) given the truth itself (net buoyancy and CG x at the
  // log's water, sigmas near zero; the roll at cruise is measured) says
  // what that best is; a plan is judged against it.
  // Each move is judged against what the kit reaches from the pieces
  // installed before it (the second move starts from the first one's).
  auto kitBest = [&](nlohmann::json oracle, double net_kg, double cg_x_m, const std::vector<double>& installed_now,
                     CaseResult::Outcome& o) {
    oracle["net_buoyancy_kg"] = net_kg;
    oracle["net_buoyancy_sigma_kg"] = 0.01;
    oracle["cg_offset_mm"]["x"] = units::mToMm(cg_x_m);
    oracle["cg_offset_sigma_mm"]["x"] = 0.01;
    const PreMissionPlan best = planFrom(oracle, installed_now).first;
    o.kit_best_roll_deg = best.predicted.roll_deg;
    o.kit_best_pitch_deg = best.flight_pitch_after_deg.value_or(best.predicted.pitch_deg);
  };
  kitBest(rj, net_truth, f.cg_x_m, kInstalled, r.one);
  r.kit_best_roll_deg = r.one.kit_best_roll_deg;
  r.kit_best_pitch_deg = r.one.kit_best_pitch_deg;
  auto judge = [&](const Flown& fl, const analysis::AnalysisReport& rp, CaseResult::Outcome& o) {
    o.net_op_kg = resolvePoint(profile_.hull, next).displaced_kg - fl.mass_kg;
    o.min_net_kg = fl.min_net_kg;
    // The attitude the vehicle flies: a biased sensor's reading less its bias.
    o.pitch_deg = cruisePitchDeg(rp, *std::max_element(m.rpms.begin(), m.rpms.end())) - effects.pitch_bias_deg;
    o.roll_deg = rp.cruise_roll_deg.known ? rp.cruise_roll_deg.value : rp.roll_deg.mean;
    o.roll_reach_deg = units::radToDeg(std::atan(0.5 * y_point / (fl.mass_kg * fl.bg_m)));
    o.net_ok = o.net_op_kg >= s.net_buoyancy_min_kg && o.net_op_kg <= s.net_buoyancy_max_kg;
    // Within the band, or within the band's half-width of the best the kit
    // allows (a CG x of 25 mm is more than some kits can move).
    o.pitch_ok = std::abs(o.pitch_deg) <= s.pitch_tolerance_deg ||
                 std::abs(o.pitch_deg - o.kit_best_pitch_deg) <= s.pitch_tolerance_deg;
    o.roll_ok = std::abs(o.roll_deg) <= std::max(s.roll_tolerance_deg, std::abs(o.kit_best_roll_deg)) + 0.5 * o.roll_reach_deg;
    o.safe = o.min_net_kg >= 0.0;
    o.spec = o.net_ok && o.pitch_ok && o.roll_ok && o.safe;
  };
  // One move from the survey's analysis. The same vehicle with other pieces:
  // its own (hidden) error stays.
  const auto [plan, after] = planFrom(rj, kInstalled);
  r.plan_band_lo_kg = plan.band_lo_kg;
  r.plan_band_hi_kg = plan.band_hi_kg;
  r.plan_net_kg = plan.predicted.net_buoyancy_kg;
  r.plan_pitch_deg = plan.flight_pitch_after_deg.value_or(plan.predicted.pitch_deg);
  r.plan_roll_deg = plan.predicted.roll_deg;
  r.one.planned_roll_deg = plan.predicted.roll_deg;
  r.one.planned_net_kg = plan.predicted.net_buoyancy_kg;
  r.manoeuvre_asked = plan.calibration_manoeuvre.has_value();
  r.plan_after_move_sigma_kg = plan.after_move_net_sigma_kg;
  for (const Message& n : plan.notes) r.plan_note_ids.push_back(n.id());
  if (r.manoeuvre_asked)
    r.manoeuvre_expected_sigma_kg = plan.calibration_manoeuvre->at("expected_sigma").at("net_buoyancy_kg").get<double>();
  if (r.manoeuvre_asked && plan.calibration_manoeuvre->contains("flight"))
    r.manoeuvre_flight = plan.calibration_manoeuvre->at("flight");
  sim::SurveyMission m2m = m2;
  if (fly_manoeuvre && plan.calibration_manoeuvre) r.manoeuvre_flown = appendManoeuvre(*plan.calibration_manoeuvre, op_depth, m2m);
  const Flown f2 = fly(truth, nominal_.autopilot, m2m, sim::installedWeights(profile_, after), err, seed * 7 + 2, after, effects);
  if (!dump_prefix.empty()) writeInterchangeCsv(f2.log, dump_prefix + "-2.csv");
  // Mission 2 analysed with mission 1 as history (the known move calibrates).
  analysis::AnalysisOptions a2;
  a2.log_name = "identification, second mission";
  a2.installed_kg = after;
  a2.bg_m = f2.bg_m;
  a2.history = {analysis::historyMissionOf(rep, kInstalled)};
  a2.use_transients = use_transients;
  a2.pitch_alignment_sigma_deg = alignment_sigma_deg;
  a2.coefficient_rel_sigma = coefficient_sigma;
  const analysis::AnalysisReport rep2 = analysis::analyzeMission(f2.log, told, a2);
  if (!dump_prefix.empty()) std::ofstream(dump_prefix + "-2.json") << analysis::toJson(rep2).dump(1) << "\n";
  r.looped = true;
  judge(f2, rep2, r.one);
  if (!rep2.net_buoyancy_kg.known) return r;
  // The second move, planned from the jointly calibrated second mission.
  const nlohmann::json rj2 = analysis::toJson(rep2);
  const double net2_truth = rep2.density_kgm3.mean * profile_.hull.volumeAt(rep2.temperature_degC.mean, rep2.pressure_dbar.mean) - f2.mass_kg;
  if (on_second_log) on_second_log(f2.log, a2, net2_truth, units::mToMm(f2.cg_x_m));
  kitBest(rj2, net2_truth, f2.cg_x_m, after, r.two);
  const auto [plan2, after2] = planFrom(rj2, after);
  r.two.planned_roll_deg = plan2.predicted.roll_deg;
  r.two.planned_net_kg = plan2.predicted.net_buoyancy_kg;
  const Flown f3 = fly(truth, nominal_.autopilot, m2, sim::installedWeights(profile_, after2), err, seed * 7 + 3, after2, effects);
  judge(f3, analyse(f3, told, after2, use_transients, alignment_sigma_deg, coefficient_sigma), r.two);
  r.twice = true;
  r.net2_err_kg = rep2.net_buoyancy_kg.value - net2_truth;
  r.net2_sigma_kg = rep2.net_buoyancy_kg.sigma;
  r.x2_sigma_mm = rep2.cg_x_mm.sigma;
  r.x2_err_mm = rep2.cg_x_mm.value - units::mToMm(f2.cg_x_m);
  return r;
}

}  // namespace auv::identification

