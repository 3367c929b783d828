// A history mission analysed before a pitch sensor bias was accepted keeps
// its legs as the sensor read them; the next mission's analysis, with the
// bias accepted, takes it out of its own log and must read the history's
// legs the same way (analysis/mission_analysis.h, HistoryMission). Oracles:
// the same experiment with the history analysed after the accept, and the
// simulator's truth (a HUGIN truth whose pitch sensor reads 1 deg high).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/auv_steady_model.h"
#include "analysis/calibration_parameter.h"
#include "analysis/calibration_segments.h"
#include "common/units.h"
#include "analysis/mission_analysis.h"
#include "discrepancy/held_law_retest.h"
#include "identification_harness.h"

namespace auv::identification {
namespace {

// A steady window's cycle products are its means' products: raised by a
// bias, they must be the raised means' products (the oracle is
// balanceRegressors itself), and raising back returns the segment.
TEST(HistoryWithAcceptedBias, ASegmentRaisedByABiasIsTheSegmentThatSensorWouldHaveRead) {
  const auto mean = [](double v) {
    analysis::MeanEstimate m;
    m.mean = v;
    m.n = 300;
    return m;
  };
  analysis::SteadySegmentMeans s;
  s.speed_mps = mean(1.9);
  s.pitch_deg = mean(1.2);
  s.roll_deg = mean(-0.4);
  s.elevator_deg = mean(-3.0);
  s.depth_rate_mps = mean(0.01);
  s.density_kgm3 = 1026.0;
  const auto flight = [](const analysis::SteadySegmentMeans& g) {
    return analysis::SteadyFlight{g.speed_mps.mean, units::degToRad(g.pitch_deg.mean), units::degToRad(g.roll_deg.mean),
                                  g.elevator_deg.mean, g.depth_rate_mps.mean, g.density_kgm3};
  };
  s.regressors = analysis::balanceRegressors(flight(s));
  const analysis::SteadySegmentMeans up = analysis::withAttitudeRaised(s, 1.0, 0.25);
  EXPECT_DOUBLE_EQ(up.pitch_deg.mean, 2.2);
  EXPECT_DOUBLE_EQ(up.roll_deg.mean, -0.15);
  const analysis::BalanceRegressors want = analysis::balanceRegressors(flight(up));
  ASSERT_TRUE(up.regressors.has_value());
  EXPECT_NEAR(up.regressors->cc, want.cc, 1e-12);
  EXPECT_NEAR(up.regressors->sin_theta, want.sin_theta, 1e-12);
  EXPECT_NEAR(up.regressors->u_w, want.u_w, 1e-12);
  EXPECT_NEAR(up.regressors->au_w, want.au_w, 1e-12);
  EXPECT_NEAR(up.regressors->aw_w, want.aw_w, 1e-12);
  EXPECT_NE(up.regressors->sin_theta, s.regressors->sin_theta);
  const analysis::SteadySegmentMeans back = analysis::withAttitudeRaised(up, -1.0, -0.25);
  EXPECT_NEAR(back.pitch_deg.mean, s.pitch_deg.mean, 1e-12);
  EXPECT_NEAR(back.regressors->u_w, s.regressors->u_w, 1e-12);
  // No roll logged: the roll stays unknown.
  analysis::SteadySegmentMeans no_roll = s;
  no_roll.roll_deg = {};
  EXPECT_FALSE(analysis::withAttitudeRaised(no_roll, 1.0, 0.25).roll_deg.valid());
}

TEST(HistoryWithAcceptedBias, AMissionAnalysedBeforeTheBiasWasAcceptedJoinsOnTheSameFooting) {
  Harness h;
  h.concealed.pitch_bias_deg = 1.0;
  h.pitch_alignment_sigma_deg = 0.0;  // the pitch read as true: the accepted bias is the only correction
  MissionLog first;
  analysis::AnalysisReport first_rep;
  h.on_first_log = [&](const MissionLog& log, const analysis::AnalysisReport& rep, double, double) {
    first = log;
    first_rep = rep;
  };
  int called = 0;
  h.on_second_log = [&](const MissionLog& log, const analysis::AnalysisOptions& a, double net_truth, double x_truth) {
    ++called;
    ASSERT_EQ(a.history.size(), 1u);
    EXPECT_EQ(a.history[0].pitch_bias_removed_deg, 0.0);  // analysed before the accept
    VehicleProfile accepted = h.profile();
    accepted.sections["model_check"]["terms"]["pitch_sensor_bias"] = 1.0;
    const analysis::AnalysisReport joint = analysis::analyzeMission(log, accepted, a);
    ASSERT_TRUE(joint.net_buoyancy_kg.known && joint.cg_x_mm.known);
    EXPECT_GT(joint.details["auv_estimate"].value("history_segments_used", 0), 0);
    EXPECT_EQ(joint.pitch_bias_removed_deg, 1.0);
    EXPECT_EQ(joint.details["auv_estimate"]["attitude_bias_removed_deg"]["pitch"].get<double>(), 1.0);

    // The same experiment, the first mission analysed with the bias accepted.
    analysis::AnalysisOptions first_opts;
    first_opts.installed_kg = a.history[0].installed_kg;
    first_opts.bg_m = analysis::calibrationParameter(first_rep, "bg")->value;
    first_opts.pitch_alignment_sigma_deg = 0.0;
    const analysis::AnalysisReport first_fixed = analysis::analyzeMission(first, accepted, first_opts);
    EXPECT_EQ(first_fixed.pitch_bias_removed_deg, 1.0);
    analysis::AnalysisOptions same = a;
    same.history = {analysis::historyMissionOf(first_fixed, a.history[0].installed_kg)};
    const analysis::AnalysisReport reference = analysis::analyzeMission(log, accepted, same);
    ASSERT_TRUE(reference.net_buoyancy_kg.known);
    EXPECT_NEAR(joint.net_buoyancy_kg.value, reference.net_buoyancy_kg.value, 0.2 * reference.net_buoyancy_kg.sigma);
    EXPECT_NEAR(joint.cg_x_mm.value, reference.cg_x_mm.value, 0.2 * reference.cg_x_mm.sigma);

    EXPECT_LE(std::abs(joint.net_buoyancy_kg.value - net_truth), 2.0 * joint.net_buoyancy_kg.sigma)
        << joint.net_buoyancy_kg.value << " +- " << joint.net_buoyancy_kg.sigma << " truth " << net_truth;
    EXPECT_LE(std::abs(joint.cg_x_mm.value - x_truth), 2.0 * joint.cg_x_mm.sigma)
        << joint.cg_x_mm.value << " +- " << joint.cg_x_mm.sigma << " truth " << x_truth;

    // Control: the stored legs read as if the bias had been out of them.
    analysis::AnalysisOptions stale = a;
    stale.history[0].pitch_bias_removed_deg = 1.0;
    const analysis::AnalysisReport wrong = analysis::analyzeMission(log, accepted, stale);
    ASSERT_TRUE(wrong.net_buoyancy_kg.known);
    EXPECT_GT(std::abs(wrong.net_buoyancy_kg.value - net_truth), 2.0 * wrong.net_buoyancy_kg.sigma)
        << wrong.net_buoyancy_kg.value << " +- " << wrong.net_buoyancy_kg.sigma << " truth " << net_truth;
    EXPECT_GT(std::abs(wrong.cg_x_mm.value - x_truth), 3.0 * wrong.cg_x_mm.sigma)
        << wrong.cg_x_mm.value << " +- " << wrong.cg_x_mm.sigma << " truth " << x_truth;
  };
  h.run(5501, true);
  EXPECT_EQ(called, 1);
}

// The model check that finds a pitch sensor bias analyses the log again
// with it taken out (followFoundPitchBias). With a configuration's history
// that second analysis must keep the history, re-referenced to the found
// bias, as the analysis the check held did: analysed alone its net
// buoyancy is the single log's, wider and elsewhere. Oracle: analyzeMission
// given the same options and the profile with the bias accepted.
TEST(HistoryWithAcceptedBias, TheChecksAnalysisWithoutTheFoundBiasKeepsTheHistory) {
  Harness h;
  h.concealed.pitch_bias_deg = 1.0;
  h.pitch_alignment_sigma_deg = 0.0;  // the pitch read as true: the whole bias is the check's to find
  int called = 0;
  h.on_second_log = [&](const MissionLog& log, const analysis::AnalysisOptions& a, double net_truth, double) {
    ++called;
    ASSERT_EQ(a.history.size(), 1u);
    const analysis::AnalysisReport rep = analysis::analyzeMission(log, h.profile(), a);
    ASSERT_TRUE(rep.options.has_value());
    EXPECT_EQ(rep.options->history.size(), 1u);
    // The check's finding, as runModelCheck reports a pitch sensor bias.
    discrepancy::ModelCheckResult found;
    discrepancy::MissingPhysics bias;
    bias.id = "pitch_sensor_bias";
    bias.unit = "deg";
    bias.value = 1.0;
    bias.sigma = 0.05;
    found.missing_physics.push_back(bias);
    discrepancy::ModelCheckResult alone = found;

    discrepancy::followFoundPitchBias(log, h.profile(), rep, found);
    ASSERT_TRUE(found.analysis_without_pitch_bias.has_value());
    const auto& free = *found.analysis_without_pitch_bias;
    VehicleProfile accepted = h.profile();
    accepted.sections["model_check"]["terms"]["pitch_sensor_bias"] = 1.0;
    accepted.sections["model_check"]["accepted"] =
        nlohmann::json::array({{{"id", "pitch_sensor_bias"}, {"sigma", 0.05}}});
    const analysis::AnalysisReport joint = analysis::analyzeMission(log, accepted, a);
    ASSERT_TRUE(joint.net_buoyancy_kg.known);
    EXPECT_GT(joint.details["auv_estimate"].value("history_segments_used", 0), 0);
    EXPECT_NEAR(free.net_buoyancy_kg, joint.net_buoyancy_kg.value, 1e-9);
    EXPECT_NEAR(free.net_buoyancy_sigma_kg, joint.net_buoyancy_kg.sigma, 1e-9);
    EXPECT_LE(std::abs(free.net_buoyancy_kg - net_truth), 2.0 * free.net_buoyancy_sigma_kg)
        << free.net_buoyancy_kg << " +- " << free.net_buoyancy_sigma_kg << " truth " << net_truth;

    // Control: a report that does not keep its options (one read back from
    // JSON) is analysed again from what its details hold: the log alone.
    analysis::AnalysisReport bare = rep;
    bare.options.reset();
    discrepancy::followFoundPitchBias(log, h.profile(), bare, alone);
    ASSERT_TRUE(alone.analysis_without_pitch_bias.has_value());
    EXPECT_GT(alone.analysis_without_pitch_bias->net_buoyancy_sigma_kg, 1.5 * free.net_buoyancy_sigma_kg)
        << alone.analysis_without_pitch_bias->net_buoyancy_sigma_kg << " vs " << free.net_buoyancy_sigma_kg;
  };
  h.run(5501, true);
  EXPECT_EQ(called, 1);
}

}  // namespace
}  // namespace auv::identification
