// Which ballast state the plan uses after an analysis and its model check
// (issue 14 item 5): the rules, on hand-made reports.
#include <gtest/gtest.h>

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

TEST(PlanEstimate, AcceptedTermsAdoptTheChecksNetBuoyancyAndCgXButNotCgY) {
  const ModelCheckResult c = check();
  const PlanEstimate e = planEstimate(analysisReport(), &c, {"quadratic_pitch_damping"});
  EXPECT_EQ(e.source, EstimateSource::kModelCheck);
  EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.value, 2.88);
  EXPECT_DOUBLE_EQ(e.report.net_buoyancy_kg.sigma, 0.07);
  EXPECT_DOUBLE_EQ(e.report.cg_x_mm.value, 0.07);
  EXPECT_DOUBLE_EQ(e.report.cg_x_mm.sigma, 0.06);
  EXPECT_FALSE(e.report.cg_y_mm.known);  // still not known: no BG
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

}  // namespace
}  // namespace auv::discrepancy
