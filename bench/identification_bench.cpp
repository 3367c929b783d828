// Issue 11 proof: over drawn truths (hydrodynamic groups x0.6-1.4, Munk
// moment inside M_w or on top, propeller torque 0-2x, stern planes x0.6-1.2,
// BG 12-30 mm, CG x +-25 mm, y +-3 mm, net +1..+8 kg) flying 2-4 h survey
// missions in stratified water with internal waves, noise and drop-outs, the
// analysis given only the nominal profile: median and 90th percentile
// |error| of net buoyancy, CG x, CG y, 2-sigma coverage, the closed loop
// after one and two moves, the second mission's joint (history) estimate
// with its coverage, and the analysis time of a 3 h 1 Hz and a 24 h 10 Hz log.
//   identification_bench [--truths N] [--seed S] [--no-loop] [--no-timing] [--verbose] [--log-interval S]
// (--log-interval: row interval of the flown logs, default 1 s; --transients:
// the analysis also fits the transients, auv_transient_fit.h; --fly-manoeuvre:
// the second mission also flies the calibration manoeuvre the first plan
// asked for, details.calibration_manoeuvre.flight; --model-check N: the
// model check of the first N logs, which conceal no effect, run with each
// log's analysis as the CLI and the wizard run it: the terms it names there
// are false, and how often its own ballast fit and the one the
// plan adopts with all its terms accepted (planEstimate) cover the truth;
// --pitch-alignment-sigma DEG: the analysis's prior on the sensor's bias
// (default 1; 0 = the pitch read as true). --pitch-bias DEG: every
// mission's pitch sensor reads DEG too high, as in
// hugin_concealed_bench's pitch-bias case; --level-check DEG: the sensor
// was level-checked within +-DEG (the configuration's pitch_level_check_deg):
// each truth's bias is drawn uniformly in that tolerance and the analysis's
// prior is DEG (it replaces the two flags before); --analysis-knows-truth R:
// the diagnostic that gives the analysis and the plans each truth's own
// hydrodynamics with a relative prior sigma R (what still misses is the
// analysis's model structure, not its coefficients); --sigma-factor K: k of the
// plans' safety margin, default 1.645; --dump SEED PREFIX writes one
// truth's logs and first report for the CLI and the wizard)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "analysis/calibration_parameter.h"
#include "analysis/mission_analysis.h"
#include "discrepancy/held_law_retest.h"
#include "discrepancy/model_check.h"
#include "discrepancy/plan_estimate.h"
#include "discrepancy/vehicle_check.h"
#include "identification_harness.h"
#include "sim/sim_log.h"
#include "sim/simulator.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"
#include "sim/truth_draw.h"
#include <fstream>

namespace {

using namespace auv;

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(pos);
  const double f = pos - static_cast<double>(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

// The first log's flight-envelope findings, for the verbose line.
std::string envelopeTags(const identification::CaseResult& r) {
  std::string t;
  if (r.too_light) t += " too-light";
  if (r.too_heavy) t += " too-heavy";
  if (r.porpoising) t += " porpoising";
  return t.empty() ? t : " | envelope:" + t;
}

double timeAnalysis(const identification::Harness& h, double duration_s, double interval_s) {
  sim::SurveyRanges r;
  r.duration_min_s = r.duration_max_s = duration_s;
  r.trace_interval_s = interval_s;
  r.speeds_min = 3;
  const sim::SurveyMission m = sim::makeSurveyMission(99, r);
  const sim::SimVehicle v =
      sim::loadSimVehicle(loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/hugin1000.json"), AUV_RESOURCE_DIR);
  sim::Scenario sc = m.scenario;
  sc.extra_masses = sim::installedWeights(h.profile(), std::vector<double>{7.2, 7.2, 25.2, 25.2});
  const sim::SimTrace tr = sim::simulate(v.model, v.autopilot, m.water(), sc, m.options);
  MissionLog log = sim::toMissionLog(tr, {"hugin1000", "plan", "timing", 99, 0, {7.2, 7.2, 25.2, 25.2}, {sim::latitudeMetadata(m.latitude_deg)}});
  sim::applyDropouts(log, 99);
  analysis::AnalysisOptions a;
  a.installed_kg = {7.2, 7.2, 25.2, 25.2};
  a.bg_m = 0.02;
  a.use_transients = h.use_transients;
  double best = 1e30;
  for (int k = 0; k < 3; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    const analysis::AnalysisReport rep = analysis::analyzeMission(log, h.profile(), a);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (rep.rows == 0) std::puts("empty");
  }
  std::printf("  %zu rows\n", log.rowCount());
  return best;
}

}  // namespace

// The model check on logs that conceal no effect (issue 11 item 6): every
// term it names is false; its own ballast fit, and the one the plan adopts
// with all its terms accepted (discrepancy::planEstimate), against the truth.
struct ModelCheckTally {
  int logs = 0, with_terms = 0, check_cov = 0, plan_net_cov = 0, plan_x_cov = 0, plan_known = 0, x_known = 0;
  std::map<std::string, int> terms;
  std::vector<double> check_z, plan_z;  // |error| / sigma of net buoyancy
  void add(const MissionLog& log, const VehicleProfile& v, const analysis::AnalysisReport& rep, double net_truth,
           double x_truth, bool verbose) {
    discrepancy::CheckSetup setup;
    setup.analysis = &rep;  // as the CLI and the wizard check a log: with its analysis
    discrepancy::ModelCheckResult r =
        discrepancy::runModelCheck(*discrepancy::makeCheckModel(log, v, AUV_RESOURCE_DIR, setup));
    discrepancy::followFoundPitchBias(log, v, rep, r);
    ++logs;
    std::vector<std::string> ids;
    for (const auto& m : r.missing_physics) ids.push_back(m.id), ++terms[m.id];
    with_terms += !ids.empty();
    if (std::isfinite(r.net_buoyancy_kg) && r.net_buoyancy_sigma_kg > 0) {
      check_z.push_back(std::abs(r.net_buoyancy_kg - net_truth) / r.net_buoyancy_sigma_kg);
      check_cov += check_z.back() <= 2.0;
    }
    const discrepancy::PlanEstimate e = discrepancy::planEstimate(rep, &r, ids);
    if (e.report.net_buoyancy_kg.known && e.report.net_buoyancy_kg.sigma > 0) {
      ++plan_known;
      plan_z.push_back(std::abs(e.report.net_buoyancy_kg.value - net_truth) / e.report.net_buoyancy_kg.sigma);
      plan_net_cov += plan_z.back() <= 2.0;
    }
    if (e.report.cg_x_mm.known && e.report.cg_x_mm.sigma > 0) {
      ++x_known;
      plan_x_cov += std::abs(e.report.cg_x_mm.value - x_truth) <= 2.0 * e.report.cg_x_mm.sigma;
    }
    if (verbose)
      std::printf("  model check: %zu term(s)%s, check's net %+.3f +- %.3f kg, plan's %+.3f +- %.3f kg, truth %+.3f kg\n",
                  ids.size(), ids.empty() ? "" : (" (" + ids.front() + (ids.size() > 1 ? ", ..." : "") + ")").c_str(),
                  r.net_buoyancy_kg, r.net_buoyancy_sigma_kg, e.report.net_buoyancy_kg.value, e.report.net_buoyancy_kg.sigma,
                  net_truth);
  }
  void print() const {
    std::printf("  model check on %d logs with no concealed effect: terms named on %d (false):", logs, with_terms);
    for (const auto& [id, n] : terms) std::printf(" %s %d,", id.c_str(), n);
    std::printf("\n    the check's own ballast fit: net within 2 sigma %d of %zu (|error|/sigma median %.1f); "
                "the plan's with every term accepted: net %d of %d (median %.2f), CG x %d of %d\n",
                check_cov, check_z.size(), quantile(check_z, 0.5), plan_net_cov, plan_known, quantile(plan_z, 0.5),
                plan_x_cov, x_known);
  }
};

int main(int argc, char** argv) {
  int truths = 50;
  std::uint64_t seed = 1100;
  bool loop = true, timing = true, verbose = false, fly_manoeuvre = false;
  double log_interval_s = 1.0, pitch_bias_deg = 0.0, level_check_deg = 0.0, knows_truth = 0.0, alignment_sigma_deg = 1.0, sigma_factor = PreMissionInput{}.sigma_factor;
  bool transients = false;
  int model_checks = 0;
  auto configure = [&](identification::Harness& h) {
    h.log_interval_s = log_interval_s;
    h.use_transients = transients;
    h.fly_manoeuvre = fly_manoeuvre;
    h.sigma_factor = sigma_factor;
    h.concealed.pitch_bias_deg = pitch_bias_deg;
    h.pitch_alignment_sigma_deg = alignment_sigma_deg;
    h.level_check_deg = level_check_deg;
    h.analysis_knows_truth_rel_sigma = knows_truth;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--truths" && i + 1 < argc) truths = std::atoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--no-loop") loop = false;
    else if (a == "--no-timing") timing = false;
    else if (a == "--verbose") verbose = true;
    else if (a == "--fly-manoeuvre") fly_manoeuvre = true;
    else if (a == "--log-interval" && i + 1 < argc) log_interval_s = std::atof(argv[++i]);
    else if (a == "--transients") transients = true;
    else if (a == "--pitch-bias" && i + 1 < argc) pitch_bias_deg = std::atof(argv[++i]);  // a concealed sensor bias
    else if (a == "--pitch-alignment-sigma" && i + 1 < argc) alignment_sigma_deg = std::atof(argv[++i]);  // 0: read as true
    else if (a == "--level-check" && i + 1 < argc) level_check_deg = std::atof(argv[++i]);  // a bias within +-DEG, known
    else if (a == "--analysis-knows-truth" && i + 1 < argc) knows_truth = std::atof(argv[++i]);
    else if (a == "--sigma-factor" && i + 1 < argc) sigma_factor = std::atof(argv[++i]);  // k of the plans' margin
    else if (a == "--model-check" && i + 1 < argc) model_checks = std::atoi(argv[++i]);
    else if (a == "--truth-doc" && i + 2 < argc) {  // --truth-doc SEED FILE: the truth's hydrodynamics companion
      const nlohmann::json nominal = JsonReader::parseFile(std::string(AUV_RESOURCE_DIR) + "/sim/hugin1000_hydrodynamics.json");
      std::ofstream(argv[i + 2]) << sim::truthHydrodynamicsDoc(nominal, sim::drawTruth(std::strtoull(argv[i + 1], nullptr, 10))).dump(1) << "\n";
      return 0;
    }
    else if (a == "--dump" && i + 2 < argc) {  // --dump SEED PREFIX: logs and reports of one truth (first; -2: second, joint)
      // The flags given before it apply (--fly-manoeuvre, --log-interval, --transients, --pitch-bias, --pitch-alignment-sigma, --level-check, --analysis-knows-truth, --sigma-factor).
      identification::Harness h;
      configure(h);
      const auto r = h.run(std::strtoull(argv[i + 1], nullptr, 10), true, argv[i + 2]);
      std::printf("%s\n", r.truth.describe().c_str());
      return 0;
    }
    else {
      std::fprintf(stderr, "usage: identification_bench [--truths N] [--seed S] [--no-loop] [--no-timing] [--verbose] [--log-interval S] [--transients] [--fly-manoeuvre] [--pitch-bias DEG] [--pitch-alignment-sigma DEG] [--level-check DEG] [--analysis-knows-truth R] [--sigma-factor K] [--model-check N] [--dump SEED PREFIX]\n");
      return 2;
    }
  }
  identification::Harness h;
  configure(h);
  std::vector<double> en, ex, ey, en2, ex2, zn, zx;  // zn, zx: |error| / sigma
  int flagged = 0, light = 0, heavy = 0, porpoise = 0, flagged_miss2 = 0, clean = 0, clean_spec2 = 0;
  std::vector<double> droll1, dpitch1;  // |flown after one move - the plan's prediction|
  int known = 0, cov_n = 0, cov_x = 0, cov_y = 0, y_known = 0, cov_n2 = 0, cov_x2 = 0;
  int looped = 0, spec = 0, net_ok = 0, pitch_ok = 0, roll_ok = 0, safe = 0, n3 = 0, spec3 = 0;
  int spec2 = 0, net2 = 0, pitch2 = 0, roll2 = 0, safe2 = 0, spec23 = 0, twice = 0, asked = 0, flown = 0;
  std::map<std::string, int> identified;
  int laws_used = 0, conflicted = 0;
  ModelCheckTally mc;
  if (model_checks > 0)
    h.on_first_log = [&](const MissionLog& log, const analysis::AnalysisReport& rep, double net_truth, double x_truth) {
      if (mc.logs < model_checks) mc.add(log, h.profile(), rep, net_truth, x_truth, verbose);
    };
  for (int i = 0; i < truths; ++i) {
    const identification::CaseResult r = h.run(seed + static_cast<std::uint64_t>(i), loop);
    if (verbose)
      std::printf("%s | pitch sensor %+.2f deg | %d speeds %d depths | net %+.3f (s %.3f) x %+.2f (s %.2f) mm y %+.3f (s %.3f) mm%s\n",
                  r.truth.describe().c_str(), r.pitch_bias_deg, r.speeds, r.depths, r.net_err_kg, r.net_sigma_kg, r.x_err_mm,
                  r.x_sigma_mm, r.y_err_mm, r.y_sigma_mm,
                  r.looped ? (std::string(" | log speeds ") + std::to_string(r.log_rpms.size()) + " | plan band " +
                              std::to_string(r.plan_band_lo_kg) + ".." + std::to_string(r.plan_band_hi_kg) +
                              " net " + std::to_string(r.plan_net_kg) + " pitch " + std::to_string(r.plan_pitch_deg) +
                              " roll " + std::to_string(r.plan_roll_deg) + " (kit best " + std::to_string(r.kit_best_roll_deg) +
                              ") | one move: net " +
                              std::to_string(r.one.net_op_kg) + " (min " + std::to_string(r.one.min_net_kg) + ") pitch " +
                              std::to_string(r.one.pitch_deg) + " roll " + std::to_string(r.one.roll_deg) +
                              (r.one.spec ? " SPEC" : " miss") + " | two: net " + std::to_string(r.two.net_op_kg) + " (min " + std::to_string(r.two.min_net_kg) + ")" +
                              " pitch " + std::to_string(r.two.pitch_deg) + " roll " + std::to_string(r.two.roll_deg) +
                              " (planned net " + std::to_string(r.two.planned_net_kg) + " roll " + std::to_string(r.two.planned_roll_deg) +
                              ", kit best " + std::to_string(r.two.kit_best_roll_deg) + ")" + (r.two.spec ? " SPEC" : " miss") + " | joint net err " + std::to_string(r.net2_err_kg) +
                              " s " + std::to_string(r.net2_sigma_kg) + " (predicted " +
                              std::to_string(r.after_move_expected_sigma_kg) + ") x err " + std::to_string(r.x2_err_mm) + " s " + std::to_string(r.x2_sigma_mm) +
                              " (predicted " + std::to_string(r.after_move_expected_x_sigma_mm) + ")" +
                              (r.manoeuvre_asked ? " manoeuvre expected s " + std::to_string(r.manoeuvre_expected_sigma_kg) +
                                                       (r.manoeuvre_flown ? " flown" : " not flown")
                                                 : std::string()) +
                              envelopeTags(r))
                                 .c_str()
                           : envelopeTags(r).c_str());
    for (const auto& q : r.calibration) identified[q.id] += q.identified ? 1 : 0;
    bool lawsUsed = false;  // the truths fly the profile's hull law and mass: each kept is a false one
    for (const auto& q : r.calibration) lawsUsed = lawsUsed || (q.id == "mass_drift" && q.used);
    laws_used += lawsUsed ? 1 : 0;
    bool conflict = false;
    for (const auto& q : r.calibration) conflict = conflict || analysis::conflictsWithPrior(q);
    conflicted += conflict ? 1 : 0;
    if (r.known) {
      ++known;
      en.push_back(std::abs(r.net_err_kg));
      ex.push_back(std::abs(r.x_err_mm));
      if (r.net_sigma_kg > 0) zn.push_back(std::abs(r.net_err_kg) / r.net_sigma_kg);
      if (r.x_sigma_mm > 0) zx.push_back(std::abs(r.x_err_mm) / r.x_sigma_mm);
      cov_n += std::abs(r.net_err_kg) <= 2 * r.net_sigma_kg;
      cov_x += std::abs(r.x_err_mm) <= 2 * r.x_sigma_mm;
    }
    if (r.y_known) {
      ++y_known;
      ey.push_back(std::abs(r.y_err_mm));
      cov_y += std::abs(r.y_err_mm) <= 2 * r.y_sigma_mm;
    }
    if (r.looped) {
      ++looped;
      if (std::isfinite(r.one.roll_deg - r.plan_roll_deg)) droll1.push_back(std::abs(r.one.roll_deg - r.plan_roll_deg));
      if (std::isfinite(r.one.pitch_deg - r.plan_pitch_deg)) dpitch1.push_back(std::abs(r.one.pitch_deg - r.plan_pitch_deg));
      spec += r.one.spec, net_ok += r.one.net_ok, pitch_ok += r.one.pitch_ok, roll_ok += r.one.roll_ok,
          safe += r.one.safe;
      spec2 += r.two.spec, net2 += r.two.net_ok, pitch2 += r.two.pitch_ok, roll2 += r.two.roll_ok,
          safe2 += r.twice && r.two.safe && r.one.safe, twice += r.twice;
      if (r.log_rpms.size() >= 3) ++n3, spec3 += r.one.spec, spec23 += r.two.spec;
      asked += r.manoeuvre_asked, flown += r.manoeuvre_flown;
      const bool off = r.too_light || r.too_heavy || r.porpoising;
      flagged += off, light += r.too_light, heavy += r.too_heavy, porpoise += r.porpoising;
      flagged_miss2 += off && !r.two.spec;
      clean += !off, clean_spec2 += !off && r.two.spec;
    }
    if (r.twice && r.net2_sigma_kg > 0.0) {
      en2.push_back(std::abs(r.net2_err_kg));
      ex2.push_back(std::abs(r.x2_err_mm));
      cov_n2 += std::abs(r.net2_err_kg) <= 2 * r.net2_sigma_kg;
      cov_x2 += std::abs(r.x2_err_mm) <= 2 * r.x2_sigma_mm;
    }
  }
  std::printf("identification bench: %d truths (seed %llu), estimates for %d\n", truths,
              static_cast<unsigned long long>(seed), known);
  std::printf("  |error|        median     p90   2-sigma coverage\n");
  std::printf("  net buoyancy  %6.3f  %6.3f kg   %3d of %d\n", quantile(en, 0.5), quantile(en, 0.9), cov_n, known);
  std::printf("  CG x          %6.2f  %6.2f mm   %3d of %d\n", quantile(ex, 0.5), quantile(ex, 0.9), cov_x, known);
  std::printf("  CG y          %6.3f  %6.3f mm   %3d of %d\n", quantile(ey, 0.5), quantile(ey, 0.9), cov_y, y_known);
  // Whether the sigmas are honest in size, not only in coverage: for a
  // Gaussian |error| / sigma has median 0.67 and 90th percentile 1.64.
  std::printf("  |error| / sigma (Gaussian: 0.67 / 1.64): net %.2f / %.2f, CG x %.2f / %.2f, median / p90\n",
              quantile(zn, 0.5), quantile(zn, 0.9), quantile(zx, 0.5), quantile(zx, 0.9));
  std::printf("  identified by the log (of %d):", truths);
  for (const auto& [id, n] : identified) std::printf(" %s %d,", id.c_str(), n);
  std::printf("\n  buoyancy laws (hull law, mass drift) kept as significant: %d of %d (the truths have the profile's)\n",
              laws_used, truths);
  std::printf("  a group more than 3 prior sigmas from its prior (analysis.calibration_prior_conflict): %d of %d\n",
              conflicted, truths);
  if (loop)
    std::printf("  second mission, joint with the first (history): net %.3f / %.3f kg (coverage %d of %zu), "
                "CG x %.2f / %.2f mm (coverage %d of %zu), median / p90\n",
                quantile(en2, 0.5), quantile(en2, 0.9), cov_n2, en2.size(), quantile(ex2, 0.5), quantile(ex2, 0.9),
                cov_x2, ex2.size());
  if (loop)
    std::printf("  one move: spec %d of %d (logs with >= 3 steady speeds: %d of %d); net %d, pitch %d, roll %d; never negative %d of %d\n",
                spec, looped, spec3, n3, net_ok, pitch_ok, roll_ok, safe, looped);
  if (loop)
    std::printf("  one move, flown - predicted by the plan: |roll| %.3f / %.3f deg, |flight pitch| %.3f / %.3f deg, "
                "median / p90\n",
                quantile(droll1, 0.5), quantile(droll1, 0.9), quantile(dpitch1, 0.5), quantile(dpitch1, 0.9));
  if (loop)
    std::printf("  two moves (second from the joint history calibration): spec %d of %d (>= 3 steady speeds: %d of %d); "
                "net %d, pitch %d, roll %d; never negative in either %d of %d flown twice\n",
                spec2, looped, spec23, n3, net2, pitch2, roll2, safe2, twice);
  if (loop)
    std::printf("  first logs not flown as commanded (details.flight_envelope): %d (too light %d, too heavy %d, "
                "porpoising %d), %d of them missed after two moves; the other logs: spec after two moves %d of %d\n",
                flagged, light, heavy, porpoise, flagged_miss2, clean_spec2, clean);
  if (loop)
    std::printf("  calibration manoeuvre: asked by %d first plans, flown in %d second missions%s\n", asked, flown,
                fly_manoeuvre ? "" : " (not flown without --fly-manoeuvre)");
  if (model_checks > 0) mc.print();
  if (timing) {
    std::printf("  analysis + calibration, 3 h at 1 Hz: %.3f s\n", timeAnalysis(h, 3 * 3600.0, 1.0));
    std::printf("  analysis + calibration, 24 h at 10 Hz: %.3f s\n", timeAnalysis(h, 24 * 3600.0, 0.1));
  }
  return 0;
}
