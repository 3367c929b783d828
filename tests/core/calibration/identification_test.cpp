// The identification harness on a few drawn truths (the full proof over 50
// is bench/identification_bench): the truth's hydrodynamics are not the
// profile's (groups x0.6-1.4, Munk inside M_w or on top, torque 0-2x,
// planes x0.6-1.2), the analysis gets only the nominal profile and the log.
// Bounds are what the calibration meets on these seeds with some headroom;
// before the calibration (flat 10 % coefficient term, profile assumed
// exact) the bench's 50 truths had 2-sigma coverage of CG x in 22 of 49.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "analysis/mission_analysis.h"
#include "discrepancy/model_check.h"
#include "discrepancy/plan_estimate.h"
#include "discrepancy/vehicle_check.h"
#include "first_log_check.h"
#include "identification_harness.h"

namespace auv::identification {
namespace {

// The truth within 2 sigma (net buoyancy, CG x), and one move flown safe
// and in the spec.
void expectCoveredAndInSpecAfterOneMove(const CaseResult& r) {
  EXPECT_LE(std::abs(r.net_err_kg), 2.0 * r.net_sigma_kg);
  EXPECT_LE(std::abs(r.x_err_mm), 2.0 * r.x_sigma_mm);
  ASSERT_TRUE(r.looped);
  EXPECT_TRUE(r.one.safe);
  EXPECT_TRUE(r.one.spec) << "net " << r.one.net_op_kg << " pitch " << r.one.pitch_deg << " roll " << r.one.roll_deg;
}

TEST(Identification, DrawnTruthsAreCoveredByThePosteriorSigma) {
  const Harness h;
  int known = 0, cov_net = 0, cov_x = 0, cov_y = 0, y_known = 0;
  std::vector<double> net_err, x_err;
  for (std::uint64_t seed = 1100; seed < 1108; ++seed) {
    const CaseResult r = h.run(seed, false);
    SCOPED_TRACE(r.truth.describe());
    if (r.known) {
      ++known;
      net_err.push_back(std::abs(r.net_err_kg));
      x_err.push_back(std::abs(r.x_err_mm));
      cov_net += std::abs(r.net_err_kg) <= 2 * r.net_sigma_kg;
      cov_x += std::abs(r.x_err_mm) <= 2 * r.x_sigma_mm;
    }
    if (r.y_known) {
      ++y_known;
      cov_y += std::abs(r.y_err_mm) <= 2 * r.y_sigma_mm;
    }
  }
  ASSERT_EQ(known, 8);
  ASSERT_EQ(y_known, 8);
  std::sort(net_err.begin(), net_err.end());
  std::sort(x_err.begin(), x_err.end());
  std::printf("  8 truths: net |err| median %.3f kg, CG x |err| median %.2f mm; coverage %d %d %d of 8\n",
              0.5 * (net_err[3] + net_err[4]), 0.5 * (x_err[3] + x_err[4]), cov_net, cov_x, cov_y);
  EXPECT_GE(cov_net, 7);
  EXPECT_GE(cov_x, 7);
  EXPECT_GE(cov_y, 7);
  EXPECT_LT(0.5 * (net_err[3] + net_err[4]), 0.3);
  EXPECT_LT(0.5 * (x_err[3] + x_err[4]), 1.0);
}

// Vehicles the steady windows lose: 1109 limit-cycles at its two lower
// speeds (pitch +-6 deg, period ~10 min), 1136 cannot hold depth at two of
// its three (the elevator at its stop, sinking at -20 deg or climbing at
// +15 deg). Before the averaged legs and the steady dives, the analysis
// kept one speed of each and stated 2.9 and 7.6 kg of sigma (now 0.4 and
// 1.3 kg, with the segments weighted over the prior's spread).
TEST(Identification, LimitCyclingAndSinkingVehiclesKeepTheirSpeeds) {
  const Harness h;
  for (std::uint64_t seed : {1109ULL, 1136ULL}) {
    const CaseResult r = h.run(seed, false);
    SCOPED_TRACE(r.truth.describe());
    ASSERT_TRUE(r.known);
    EXPECT_EQ(r.log_rpms.size(), 3u);
    EXPECT_LT(r.net_sigma_kg, 1.5);
    EXPECT_LE(std::abs(r.net_err_kg), 2.0 * r.net_sigma_kg);
    EXPECT_LE(std::abs(r.x_err_mm), 2.0 * r.x_sigma_mm);
  }
}

// The dives of a survey's depth changes are legs too. Truth 1115 (3
// speeds, 3 depths) dives and climbs at the autopilot's 15 degree limit for
// about a minute at each depth change, with the propeller speed changed at
// the same command: the settling time after the rpm change left 31 s, too
// short, and with level legs alone the net buoyancy sigma was 1.55 kg and
// the one move landed 2.4 kg positive. The pitch plateau of each dive and
// climb now joins the calibration, and where the legs scatter less than
// their propagated errors say, the chi2 bound narrows them: sigma 0.40 kg,
// in the spec after one move.
TEST(Identification, TheDivesOfTheDepthChangesJoinTheLegs) {
  const Harness h;
  const CaseResult r = h.run(1115, true);
  SCOPED_TRACE(r.truth.describe());
  ASSERT_TRUE(r.known);
  EXPECT_LT(r.net_sigma_kg, 0.6);
  expectCoveredAndInSpecAfterOneMove(r);
}

// A dive the other legs' balance cannot explain is left out, and says so
// where the technician looks: truth 1115's first dive, its elevator moved
// 6 deg (a depth change flown at an elevator no steady flight has). The
// report's segment list marks it (`calibration_dropped`, the wizard's
// "left out"), the note counts it, and it is not among the
// steady segments a later mission's history fit reads back. Tested against
// the level legs alone it passed and moved the net buoyancy 5.4 kg; against
// the level legs and the other dive it goes from 2 deg on (at 1 deg it
// stays and moves the net 1.7 kg: the dives carry the estimate).
TEST(Identification, ADiveTheLevelLegsCannotExplainIsMarkedLeftOut) {
  Harness h;
  MissionLog log;
  double bg_m = 0.0;
  h.on_first_log = [&](const MissionLog& l, const analysis::AnalysisReport& r, double, double) {
    log = l;
    bg_m = r.details.at("auv_estimate").at("bg_mm").get<double>() * 1e-3;
  };
  const CaseResult base = h.run(1115, false);
  ASSERT_TRUE(base.known);
  analysis::AnalysisOptions a;
  a.log_name = "identification";
  a.installed_kg = {7.2, 7.2, 25.2, 25.2};
  a.bg_m = bg_m;
  const analysis::AnalysisReport before = analysis::analyzeMission(log, h.profile(), a);
  const auto glide = std::find_if(before.segments.begin(), before.segments.end(), [](const analysis::SegmentReport& g) {
    return g.used && g.kind == analysis::SegmentKind::kGlide;
  });
  ASSERT_NE(glide, before.segments.end());
  EXPECT_FALSE(glide->calibration_dropped);
  const std::size_t steady_before = before.steady_segments.size();
  LogChannel& elevator = *log.find("elevator");
  for (std::size_t i = 0; i < log.rowCount(); ++i)
    if (log.time[i] >= glide->start_s - 30.0 && log.time[i] <= glide->end_s + 30.0) elevator.values[i] += 6.0;
  const analysis::AnalysisReport after = analysis::analyzeMission(log, h.profile(), a);
  const auto same = std::find_if(after.segments.begin(), after.segments.end(), [&](const analysis::SegmentReport& g) {
    return g.used && g.kind == analysis::SegmentKind::kGlide && std::abs(g.start_s - glide->start_s) < 1.0;
  });
  ASSERT_NE(same, after.segments.end());
  EXPECT_TRUE(same->calibration_dropped);
  EXPECT_NEAR(after.net_buoyancy_kg.value, before.net_buoyancy_kg.value, 2.0 * after.net_buoyancy_kg.sigma);
  EXPECT_TRUE(std::any_of(after.notes.begin(), after.notes.end(),
                          [](const Message& m) { return m.id() == "analysis.glides_dropped"; }));
  EXPECT_EQ(after.steady_segments.size(), steady_before - 1);
  for (const auto& g : after.steady_segments) EXPECT_GT(std::abs(g.start_s - same->start_s), 1.0);
  const nlohmann::json j = analysis::toJson(after);
  bool marked = false;
  for (const auto& g : j.at("segments")) marked = marked || g.value("calibration_dropped", false);
  EXPECT_TRUE(marked);
}

// Truth 1136 sinks below its command with the elevator at its stop on some
// legs and flies three speeds: its legs scatter at chi2/dof 0.002 of what
// their standard errors say. With the narrowing floored at 0.04 its net
// sigma was 0.41 kg for an error of 0.08 kg, and one move aimed at 1.15 kg
// flew 1.23 kg (out of band); at 0.01 the sigma is honest and the move lands.
TEST(Identification, QuietLegsNarrowTheSigmaTenfoldAtMost) {
  const Harness h;
  const CaseResult r = h.run(1136, true);
  SCOPED_TRACE(r.truth.describe());
  ASSERT_TRUE(r.known);
  EXPECT_LT(r.net_sigma_kg, 0.3);
  EXPECT_GT(r.net_sigma_kg, 0.21);  // the floor holds: without it 0.19 kg
  expectCoveredAndInSpecAfterOneMove(r);
}

// Logs a technician must hear about before trusting any estimate
// (flight_envelope.h): 3100 (net +6.6 kg, CG x -23 mm, planes x0.65) rises
// to the surface at the start and stays there nose up with the elevator at
// its dive stop for the whole survey; 1130 (CG x +14 mm) sinks 96 m below
// its command with the elevator at the climb stop; 2119 (BG 12 mm, heave
// x0.77) porpoises +-25 deg every 24 s on most legs. 1101 flies as
// commanded and is not flagged.
TEST(Identification, LogsNotFlownAsCommandedAreFlagged) {
  const Harness h;
  struct Case {
    std::uint64_t seed;
    bool light, heavy, porpoising;
  };
  for (const Case c : {Case{3100, true, false, false}, Case{1130, false, true, false}, Case{2119, true, false, true},
                       Case{1101, false, false, false}}) {
    const CaseResult r = h.run(c.seed, false);
    SCOPED_TRACE(r.truth.describe());
    EXPECT_EQ(r.too_light, c.light);
    EXPECT_EQ(r.too_heavy, c.heavy);
    EXPECT_EQ(r.porpoising, c.porpoising);
  }
}

// Truth 2123 flies two speeds with the elevator at 6 and 11 deg and very
// quiet means (pitch and elevator to 0.004 deg). At the prior mean the
// covariance of a segment's heave and pitch residuals is nearly singular,
// and the fit trusted that one combination: net buoyancy 4.9 kg off with a
// stated sigma of 1.4 kg (3.6 sigma), CG x 10 mm off (4.3 sigma), and the
// vehicle ended 2 kg heavy after one move. Weighted over the prior's spread
// it was net 2.7 +- 1.7 kg, CG x 6.3 +- 3.0 mm (2.1 sigma); with the steady
// middles of its depth changes as glides as well, net -0.8 +- 0.5 kg and
// CG x +0.4 +- 0.7 mm, and the move leaves it positive.
TEST(Identification, QuietTwoSpeedLogIsNotOverconfident) {
  const Harness h;
  const CaseResult r = h.run(2123, true);
  SCOPED_TRACE(r.truth.describe());
  ASSERT_TRUE(r.known);
  std::printf("  2123: net err %+.2f kg (sigma %.2f), CG x err %+.2f mm (sigma %.2f), after one move %+.2f kg\n",
              r.net_err_kg, r.net_sigma_kg, r.x_err_mm, r.x_sigma_mm, r.one.min_net_kg);
  EXPECT_LE(std::abs(r.net_err_kg), 2.0 * r.net_sigma_kg);
  EXPECT_LE(std::abs(r.x_err_mm), 2.5 * r.x_sigma_mm);
  ASSERT_TRUE(r.looped);
  EXPECT_GE(r.one.min_net_kg, 0.0);
}

// Item 5: the plan for a two-speed log whose sigma is too wide for the band
// asks for the manoeuvre, in words and as legs a mission planner can fly:
// the three 5-min speeds the log lacks at the operating depth, then a 30 m
// descent and climb at 160 rpm at 0.25 m/s, ending where it started.
// Flown by the harness (the operator doing what was asked), the second
// mission still gives the joint estimate.
TEST(Identification, AskedManoeuvreComesAsLegsAMissionPlannerCanFly) {
  Harness h;
  h.fly_manoeuvre = true;
  const CaseResult r = h.run(2123, true);
  SCOPED_TRACE(r.truth.describe());
  ASSERT_TRUE(r.looped);
  ASSERT_TRUE(r.manoeuvre_asked);
  ASSERT_TRUE(r.manoeuvre_flight.is_array());
  ASSERT_EQ(r.manoeuvre_flight.size(), 5u) << r.manoeuvre_flight.dump();
  const double rpm[] = {130, 160, 190, 160, 160}, rate[] = {0, 0, 0, 0.25, -0.25}, seconds[] = {300, 300, 300, 120, 120};
  double depth_change = 0.0;
  for (std::size_t i = 0; i < 5; ++i) {
    const nlohmann::json& l = r.manoeuvre_flight[i];
    EXPECT_DOUBLE_EQ(l.at("prop_rpm").get<double>(), rpm[i]);
    EXPECT_DOUBLE_EQ(l.at("depth_rate_mps").get<double>(), rate[i]);
    EXPECT_DOUBLE_EQ(l.at("duration_s").get<double>(), seconds[i]);
    depth_change += l.at("depth_rate_mps").get<double>() * l.at("duration_s").get<double>();
  }
  EXPECT_DOUBLE_EQ(depth_change, 0.0);
  EXPECT_GT(r.manoeuvre_expected_sigma_kg, 0.0);
  EXPECT_LT(r.manoeuvre_expected_sigma_kg, r.net_sigma_kg);
  EXPECT_TRUE(r.manoeuvre_flown);
  EXPECT_TRUE(r.twice);
  EXPECT_GE(r.one.min_net_kg, 0.0);
  // The same plan says the move itself will calibrate the next analysis,
  // with the analysis's prediction, and that this is enough for the band.
  ASSERT_TRUE(r.plan_after_move_sigma_kg.has_value());
  EXPECT_DOUBLE_EQ(*r.plan_after_move_sigma_kg, r.after_move_expected_sigma_kg);
  EXPECT_NE(std::find(r.plan_note_ids.begin(), r.plan_note_ids.end(), "plan.after_move"), r.plan_note_ids.end());
  EXPECT_NE(std::find(r.plan_note_ids.begin(), r.plan_note_ids.end(), "plan.manoeuvre"), r.plan_note_ids.end());
}

// The move is itself a calibration (items 3 and 5): the first analysis
// predicts the sigma of the next mission's survey analysed with it as
// history, assuming a move to mid-band and level flight. The harness flies
// the move the plan actually made and analyses the second mission with the
// first as history. The prediction is optimistic: on the bench the realised
// sigma is about twice the predicted one in the median (identification_bench
// --verbose, 50 truths: 2.04 on seed 1100 and 1.82 on 2100 at 25441a7, 2.19
// and 1.96 with the 2026-12-08 pitch-bias search), still far below the first
// log's own sigma, and the joint estimate's error is within 2 realised
// sigmas. On these 12 truths the median must stay within a factor of 2.5.
TEST(Identification, TheMoveCalibratesTheNextMissionAsPredicted) {
  const Harness h;
  std::vector<double> ratio;
  int covered = 0, n = 0;
  for (std::uint64_t seed = 1100; seed < 1112; ++seed) {
    const CaseResult r = h.run(seed, true);
    if (!r.twice || !(r.after_move_expected_sigma_kg > 0.0) || !(r.net2_sigma_kg > 0.0)) continue;
    SCOPED_TRACE(r.truth.describe());
    ++n;
    ratio.push_back(r.net2_sigma_kg / r.after_move_expected_sigma_kg);
    EXPECT_LT(r.after_move_expected_sigma_kg, r.net_sigma_kg);
    covered += std::abs(r.net2_err_kg) <= 2.0 * r.net2_sigma_kg;
  }
  ASSERT_GE(n, 10);
  std::sort(ratio.begin(), ratio.end());
  const double median = ratio[ratio.size() / 2];
  std::printf("  %d truths: realised / predicted sigma after the move: median %.2f (%.2f..%.2f); covered %d\n", n, median,
              ratio.front(), ratio.back(), covered);
  EXPECT_GT(median, 0.5);
  EXPECT_LT(median, 2.5);
  EXPECT_GE(covered, n - 1);
}


// Item 8: the roll the plan predicts is the roll the trimmed vehicle flies.
// A vehicle that flew its survey heavy or nose-down held depth with planes
// and pitch and went slower than it will once trimmed; the propeller torque
// falls with the advance ratio, so the log's cruise roll overstated the
// torque the trimmed vehicle meets. The analysis now predicts the trimmed
// cruise speed from the model's surge balance (trimmed_cruise.h) and the plan
// levels that torque. Planned from the logged speed, the roll after the move
// missed the plan's prediction by more than 0.15 deg on 5 of these 20 truths
// (now 1: truth 1107, whose plan lands 10 kg light of the state assumed);
// bench, seeds 1100/2100/3100: p90 0.25/0.66/0.33 -> 0.09/0.17/0.28 deg.
TEST(Identification, TheRollAfterAMoveIsPredictedAtTheTrimmedCruiseSpeed) {
  const Harness h;
  int n = 0, close = 0;
  double worst = 0.0;
  for (std::uint64_t seed = 1100; seed < 1120; ++seed) {
    const CaseResult r = h.run(seed, true);
    if (!r.looped) continue;
    SCOPED_TRACE(r.truth.describe());
    ++n;
    const double miss = std::abs(r.one.roll_deg - r.plan_roll_deg);
    close += miss <= 0.15;
    worst = std::max(worst, miss);
  }
  std::printf("  %d truths: roll after one move within 0.15 deg of the plan's in %d, worst %.2f deg\n", n, close, worst);
  ASSERT_GE(n, 18);
  EXPECT_GE(close, n - 2);
}

// The roll a move flew within max_miss_deg of what its plan predicted, and safe.
void expectRollAsPlanned(const CaseResult::Outcome& o, double max_miss_deg) {
  EXPECT_LE(std::abs(o.roll_deg - o.planned_roll_deg), max_miss_deg) << "flown " << o.roll_deg << " planned " << o.planned_roll_deg;
  EXPECT_TRUE(o.safe);
}

// Item 8 on a survey not flown as commanded: truth 4131 flew its second
// mission 12.6 kg light with the elevator at its stop on every leg (climbs
// and dives, no level flight). Balanced there, the surge model found a
// trimmed speed of 0.70 m/s at 156 rpm (logged 1.82) only where its level
// balance stops existing; the plan levelled a torque that was not there
// and the roll after the second move was -1.67 deg against +0.04 planned.
// Now no trimmed speed is predicted there and the plan levels the torque
// it measured.
TEST(Identification, NoTrimmedSpeedIsExtrapolatedFromAnElevatorAtItsStop) {
  const Harness h;
  const CaseResult r = h.run(4131, true);
  SCOPED_TRACE(r.truth.describe());
  ASSERT_TRUE(r.twice);
  expectRollAsPlanned(r.two, 0.25);
}

// Item 8 on a survey flown far from trim: truth 2127 flew its first survey
// 27 kg heavy, 45-64 deg nose down at 0.2-0.5 m/s, rolled 22 deg at cruise.
// Its roll, read as level flight, doubled the torque (1 / cos(pitch)), and
// the drag the model misses, taken from those dives, put every trimmed
// speed above 1 m/s out of reach: the plan levelled a torque twice too
// large at 0.48 m/s and the vehicle rolled -12.6 deg after the move, at
// 1.75 m/s, where the plan said -0.1. Now the heeling balance has the
// pitch, the missing drag comes from segments the model can balance (none
// here: its own drag), and the trimmed speed is predicted at 1.75 m/s.
TEST(Identification, ASurveyFlownSteeplyNoseDownLevelsTheTrimmedVehiclesRoll) {
  const Harness h;
  const CaseResult r = h.run(2127, true);
  SCOPED_TRACE(r.truth.describe());
  ASSERT_TRUE(r.looped);
  expectRollAsPlanned(r.one, 0.5);
}

// Item 6 with item 8: the model check of truth 1101 (no concealed effect)
// names a pitch-sensor bias, and its own ballast fit is about 10 sigma off
// (net 6.46 +- 0.11 kg against 5.2; its sigma is the replay fit's for its own
// structure). Accepting every term, the plan's estimate keeps the check's
// centre with the sigma widened by its difference from the analysis, and
// covers the truth (discrepancy::planEstimate).
TEST(Identification, AModelCheckFitThePlanAdoptsCoversTheTruth) {
  Harness h;
  int called = 0;
  h.on_first_log = [&](const MissionLog& log, const analysis::AnalysisReport& rep, double net_truth, double x_truth) {
    ++called;
    const discrepancy::ModelCheckResult r =
        discrepancy::runModelCheck(*discrepancy::makeCheckModel(log, h.profile(), AUV_RESOURCE_DIR));
    std::vector<std::string> ids;
    for (const auto& m : r.missing_physics) ids.push_back(m.id);
    ASSERT_FALSE(ids.empty());
    EXPECT_GT(std::abs(r.net_buoyancy_kg - net_truth), 3.0 * r.net_buoyancy_sigma_kg);
    const discrepancy::PlanEstimate e = discrepancy::planEstimate(rep, &r, ids);
    EXPECT_EQ(e.source, discrepancy::EstimateSource::kModelCheck);
    EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.value, r.net_buoyancy_kg);
    EXPECT_LE(std::abs(e.report.net_buoyancy_kg.value - net_truth), 2.0 * e.report.net_buoyancy_kg.sigma);
    EXPECT_LE(std::abs(e.report.cg_x_mm.value - x_truth), 2.0 * e.report.cg_x_mm.sigma);
  };
  h.run(1101, false);
  EXPECT_EQ(called, 1);
}


// Item 6: the same log checked the way the CLI and the wizard check it, with
// its analysis (CheckSetup::analysis): the check holds the analysis's
// calibrated groups (their ids, values and sigmas), states its net buoyancy
// in the analysis's water, names nothing, and its ballast fit lands within
// 0.15 kg of the truth (profile only: a false pitch-sensor bias and 1.2 kg;
// held: 5.24 against 5.19).
TEST(Identification, TheModelCheckHoldsTheAnalysisCalibration) {
  checkFirstLogWithItsAnalysis(1101, [](const discrepancy::ModelCheckResult& r, const analysis::AnalysisReport& rep, double net_truth,
                                        const Harness&) {
    EXPECT_TRUE(r.missing_physics.empty()) << r.missing_physics.front().id;
    EXPECT_NEAR(r.net_buoyancy_kg, net_truth, 0.15);
    // Its sigma holds the held groups' spread (joint_refit.cpp): the fit's
    // own assumes the analysis's groups exact (0.03-0.18 kg on the bench's
    // truths, covering 13 of 50); with each group one sigma off in turn it
    // is 0.21 kg here.
    EXPECT_LE(std::abs(r.net_buoyancy_kg - net_truth), 2.0 * r.net_buoyancy_sigma_kg);
    EXPECT_GT(r.net_buoyancy_sigma_kg, 0.1);
    EXPECT_LT(r.net_buoyancy_sigma_kg, 0.5);
    ASSERT_TRUE(r.reference_water.has_value());
    EXPECT_DOUBLE_EQ(r.reference_water->density_kgm3, rep.density_kgm3.mean);
    const auto analysisValue = [&](const char* id) {
      for (const auto& c : rep.calibration)
        if (c.id == id) return c;
      ADD_FAILURE() << "the analysis reports no " << id;
      return analysis::CalibrationParameter{};
    };
    int held = 0;
    for (const discrepancy::CalibrationValue& c : r.calibration) {
      if (c.id == "bg" || c.id == "heave_derivatives" || c.id == "crossflow_pitch_moment") {
        SCOPED_TRACE(c.id);
        EXPECT_TRUE(c.from_analysis);
        const auto a = analysisValue(c.id == "bg" ? "bg" : c.id == "heave_derivatives" ? "heave_lift_scale" : "crossflow_scale");
        EXPECT_NEAR(c.value, a.value, 1e-9 * std::max(1.0, std::abs(a.value)));  // held: its bounds close on the value
        EXPECT_DOUBLE_EQ(c.sigma, a.sigma);
        ++held;
      }
      if (c.id == "propeller_torque" || c.id == "roll_damping" || c.id == "surge_drag") {
        EXPECT_FALSE(c.from_analysis) << c.id;
      }
    }
    EXPECT_EQ(held, 3);
  });
}

// A drawn truth with no concealed effect on which the held check used to name
// quadratic pitch damping at x6 of the profile, the end of its plausible range
// (hugin_concealed_bench, control 5105): a fit pinned there stands in for the
// calibration's error, and its spread over the held constants cannot even be
// measured. The check now names nothing and says why.
TEST(Identification, TheModelCheckRefusesATermPinnedAtItsRange) {
  checkFirstLogWithItsAnalysis(5105, [](const discrepancy::ModelCheckResult& r, const analysis::AnalysisReport&, double net_truth,
                                        const Harness&) {
    EXPECT_TRUE(r.missing_physics.empty()) << r.missing_physics.front().id;
    EXPECT_LE(std::abs(r.net_buoyancy_kg - net_truth), 2.0 * r.net_buoyancy_sigma_kg);
    bool refused = false;
    for (const discrepancy::CandidateReport& c : r.candidates)
      refused = refused || (c.id == "quadratic_pitch_damping" && c.status.rfind("fitted at the end of its plausible range", 0) == 0);
    EXPECT_TRUE(refused);
  });
}

}  // namespace
}  // namespace auv::identification
