// Which ballast state the plan uses after an analysis and its model check
// (issue 14 item 5): the rules, on hand-made reports.
#include <gtest/gtest.h>

#include <cmath>

#include "discrepancy/model_check_report.h"
#include "discrepancy/plan_estimate.h"

namespace auv::discrepancy {
namespace {

analysis::AnalysisReport analysisReport() {
  analysis::AnalysisReport a;
  a.vehicle_kind = "auv";
  a.net_buoyancy_kg = {true, 2.29, 0.04, ""};
  a.cg_x_mm = {true, 0.4, 0.1, ""};
  a.cg_y_mm = {false, NAN, NAN, "not identifiable without BG"};
  return a;
}

ModelCheckResult check() {
  ModelCheckResult r;
  MissingPhysics m;
  m.id = "quadratic_pitch_damping";
  r.missing_physics.push_back(m);
  r.net_buoyancy_kg = 2.88;
  r.net_buoyancy_sigma_kg = 0.07;
  r.has_cg = true;
  r.cg_x_mm = 0.07;
  r.cg_x_sigma_mm = 0.06;
  r.cg_y_mm = 2.86;  // with the profile's BG: not what the plan may use
  r.cg_y_sigma_mm = 0.0;
  return r;
}

// An analysis calibrated with the configuration's earlier mission (a known
// weight change between them) keeps its estimate whatever the check says,
// as model-check --config reports it: the check fits this log alone.
TEST(PlanEstimate, AJointHistoryAnalysisKeepsItsEstimate) {
  analysis::AnalysisReport joint = analysisReport();
  joint.details["auv_estimate"]["history_segments_used"] = 3;
  const ModelCheckResult c = check();
  const PlanEstimate e = planEstimate(joint, &c, {"quadratic_pitch_damping"});
  EXPECT_EQ(e.source, EstimateSource::kHistoryJoint);
  EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.value, 2.29);
  EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.sigma, 0.04);
  EXPECT_DOUBLE_EQ(e.report.cg_x_mm.value, 0.4);
  EXPECT_EQ(planEstimate(joint, nullptr, {}).source, EstimateSource::kHistoryJoint);
  joint.details["auv_estimate"]["history_segments_used"] = 0;  // the history had nothing to add
  EXPECT_EQ(planEstimate(joint, &c, {"quadratic_pitch_damping"}).source, EstimateSource::kModelCheck);
}

// The check's centre; its sigma widened by what separates it from the
// analysis (2.88 against 2.29 +- 0.04: 0.59 kg the accepted term did not
// reconcile), so the plan's margin covers both estimators.
TEST(PlanEstimate, AcceptedTermsAdoptTheChecksNetBuoyancyAndCgXButNotCgY) {
  const ModelCheckResult c = check();
  const PlanEstimate e = planEstimate(analysisReport(), &c, {"quadratic_pitch_damping"});
  EXPECT_EQ(e.source, EstimateSource::kModelCheck);
  EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.value, 2.88);
  EXPECT_NEAR(e.report.net_buoyancy_kg.sigma, std::hypot(0.07, 2.88 - 2.29), 1e-12);
  EXPECT_DOUBLE_EQ(e.report.cg_x_mm.value, 0.07);
  EXPECT_NEAR(e.report.cg_x_mm.sigma, std::hypot(0.1, 0.07 - 0.4), 1e-12);  // the analysis's 0.1 mm is the floor
  EXPECT_FALSE(e.report.cg_y_mm.known);  // still not known: no BG
}

// Agreeing estimators: the larger sigma (the check's own assumes its model
// structure), not the smaller.
TEST(PlanEstimate, AnAgreeingCheckKeepsAtLeastTheAnalysissSigma) {
  EXPECT_NEAR(adoptedSigma(2.29, 0.04, 2.29, 0.01), 0.04, 1e-12);
  EXPECT_NEAR(adoptedSigma(2.29, 0.04, 2.29, 0.07), 0.07, 1e-12);
  EXPECT_NEAR(adoptedSigma(5.27, 0.158, 6.463, 0.113), std::hypot(0.158, 1.193), 1e-12);
}

// An accepted pitch sensor bias: the analysis side of the rule is the
// log's analysis without the bias (5.56 +- 2.0 kg, truth 5501's numbers),
// not the one that read the biased pitch as true (4.19 +- 0.38); the same
// rule in the report the CLI writes.
TEST(PlanEstimate, AnAcceptedPitchBiasWidensAgainstTheAnalysisWithoutIt) {
  analysis::AnalysisReport a = analysisReport();
  a.net_buoyancy_kg = {true, 4.19, 0.38, ""};
  ModelCheckResult c = check();
  c.missing_physics.front().id = "pitch_sensor_bias";
  c.net_buoyancy_kg = 4.67;
  c.net_buoyancy_sigma_kg = 0.70;
  c.analysis_without_pitch_bias = ModelCheckResult::BiasFreeAnalysis{0.86, 0.28, 5.56, 2.0, true, 0.3, 0.5};
  const PlanEstimate e = planEstimate(a, &c, {"pitch_sensor_bias"});
  EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.value, 4.67);
  EXPECT_NEAR(e.report.net_buoyancy_kg.sigma, std::hypot(2.0, 5.56 - 4.67), 1e-12);
  EXPECT_NEAR(e.report.cg_x_mm.sigma, std::hypot(0.5, 0.3 - 0.07), 1e-12);
  // Not accepted: the check's extra analysis plays no part.
  c.missing_physics.push_back(c.missing_physics.front());
  c.missing_physics.back().id = "quadratic_pitch_damping";
  EXPECT_NEAR(planEstimate(a, &c, {"quadratic_pitch_damping"}).report.net_buoyancy_kg.sigma, std::hypot(0.70, 4.67 - 4.19), 1e-12);
  c.missing_physics.pop_back();

  nlohmann::json j = analysis::toJson(a);
  mergeIntoAnalysisJson(j, c, true);
  EXPECT_DOUBLE_EQ(j["net_buoyancy_kg"].get<double>(), 4.67);
  EXPECT_NEAR(j["net_buoyancy_sigma_kg"].get<double>(), std::hypot(2.0, 5.56 - 4.67), 1e-12);
  EXPECT_DOUBLE_EQ(j["model_check"]["analysis_without_pitch_bias"]["net_buoyancy_kg"].get<double>(), 5.56);
  EXPECT_DOUBLE_EQ(j["model_check"]["analysis_estimate"]["net_buoyancy_kg"].get<double>(), 4.19);
}

TEST(PlanEstimate, WithoutAnAcceptedTermOfThisCheckTheAnalysisStands) {
  const ModelCheckResult c = check();
  for (const std::vector<std::string>& accepted :
       {std::vector<std::string>{}, std::vector<std::string>{"mass_drift"}}) {
    const PlanEstimate e = planEstimate(analysisReport(), &c, accepted);
    EXPECT_EQ(e.source, EstimateSource::kAnalysis);
    EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.value, 2.29);
    EXPECT_DOUBLE_EQ(e.report.cg_x_mm.value, 0.4);
  }
  EXPECT_EQ(planEstimate(analysisReport(), nullptr, {"quadratic_pitch_damping"}).source, EstimateSource::kAnalysis);
}

TEST(PlanEstimate, ZeroSigmaIsNeverAdoptedAndGlidersKeepTheirFit) {
  ModelCheckResult c = check();
  c.cg_x_sigma_mm = 0.0;
  PlanEstimate e = planEstimate(analysisReport(), &c, {"quadratic_pitch_damping"});
  EXPECT_EQ(e.source, EstimateSource::kModelCheck);
  EXPECT_DOUBLE_EQ(e.report.cg_x_mm.value, 0.4);  // the analysis's, with its sigma
  c.net_buoyancy_sigma_kg = 0.0;
  EXPECT_EQ(planEstimate(analysisReport(), &c, {"quadratic_pitch_damping"}).source, EstimateSource::kAnalysis);
  analysis::AnalysisReport g = analysisReport();
  g.vehicle_kind = "glider";
  const ModelCheckResult ok = check();
  EXPECT_EQ(planEstimate(g, &ok, {"quadratic_pitch_damping"}).source, EstimateSource::kAnalysis);
}

// Delphin2 with its tunnel thrusters running in every steady segment: the
// analysis cannot tell the net buoyancy, the check's replay (thrusters
// included) can. Its fit is the plan's, accepted terms or not, and said so.
TEST(PlanEstimate, WhereTheAnalysisCannotTellTheChecksReplayFitIsUsed) {
  analysis::AnalysisReport a = analysisReport();
  a.net_buoyancy_kg = {false, NAN, NAN, "the tunnel thrusters ran in all 5 steady segment(s)"};
  a.cg_x_mm = {false, NAN, NAN, "the tunnel thrusters ran in all 5 steady segment(s)"};
  const ModelCheckResult c = check();
  PlanEstimate e = planEstimate(a, &c, {});
  EXPECT_EQ(e.source, EstimateSource::kModelCheckReplay);
  EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.value, 2.88);
  EXPECT_DOUBLE_EQ(e.report.cg_x_mm.value, 0.07);
  EXPECT_EQ(planEstimate(a, &c, {"quadratic_pitch_damping"}).source, EstimateSource::kModelCheck);
  ModelCheckResult no_fit = check();
  no_fit.net_buoyancy_sigma_kg = NAN;
  e = planEstimate(a, &no_fit, {});
  EXPECT_EQ(e.source, EstimateSource::kAnalysis);
  EXPECT_FALSE(e.report.net_buoyancy_kg.known);
  EXPECT_EQ(planEstimate(a, nullptr, {}).source, EstimateSource::kAnalysis);
}

// The CLI's report (mergeIntoAnalysisJson) follows the same rule: an AUV's
// analysis stands until terms are accepted (--accept); then the check's
// centre with the widened sigma, the check's own fit kept beside it.
TEST(PlanEstimate, TheCliReportFollowsTheSameRule) {
  ModelCheckResult c = check();
  c.net_buoyancy_kg = 6.463;
  c.net_buoyancy_sigma_kg = 0.113;
  const nlohmann::json base = {{"vehicle_kind", "auv"},
                               {"net_buoyancy_kg", 5.273},
                               {"net_buoyancy_sigma_kg", 0.158},
                               {"cg_offset_mm", {{"x", -4.9}, {"y", nullptr}}},
                               {"cg_offset_sigma_mm", {{"x", 0.2}, {"y", nullptr}}}};
  nlohmann::json a = base;
  mergeIntoAnalysisJson(a, c, false);
  EXPECT_DOUBLE_EQ(a["net_buoyancy_kg"].get<double>(), 5.273);
  EXPECT_DOUBLE_EQ(a["net_buoyancy_sigma_kg"].get<double>(), 0.158);
  EXPECT_DOUBLE_EQ(a["model_check"]["check_estimate"]["net_buoyancy_kg"].get<double>(), 6.463);
  EXPECT_EQ(a["model_check"]["estimate_source"], "analysis (no model-check term accepted)");
  a = base;
  mergeIntoAnalysisJson(a, c, true);
  EXPECT_DOUBLE_EQ(a["net_buoyancy_kg"].get<double>(), 6.463);
  EXPECT_NEAR(a["net_buoyancy_sigma_kg"].get<double>(), std::hypot(0.158, 6.463 - 5.273), 1e-9);
  EXPECT_DOUBLE_EQ(a["cg_offset_mm"]["x"].get<double>(), 0.07);
  EXPECT_NEAR(a["cg_offset_sigma_mm"]["x"].get<double>(), std::hypot(0.2, 0.07 + 4.9), 1e-9);
  EXPECT_DOUBLE_EQ(a["model_check"]["analysis_estimate"]["net_buoyancy_kg"].get<double>(), 5.273);
}

}  // namespace
}  // namespace auv::discrepancy
