// One vehicle model (issue 11 item 1): the steady heave force and pitch
// moment the analysis inverts are the simulator's, term by term, for the
// nominal vehicle and for truths drawn away from it (Munk moment on top of
// M_w or inside it). The oracle is sim::Dynamics::breakdown, the function
// the integrator calls.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <random>

#include "analysis/auv_calibration.h"
#include "analysis/auv_steady_model.h"
#include "common/units.h"
#include "sim/dynamics.h"
#include "sim/mission_plan.h"
#include "sim/model_loader.h"
#include "sim/truth_draw.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"

namespace auv {
namespace {

const std::string kRes = AUV_RESOURCE_DIR;

VehicleProfile withCompanion(const nlohmann::json& doc) {
  VehicleProfile p = loadVehicleProfile(kRes + "/vehicles/hugin1000.json");
  for (const char* k : {"hydrodynamics", "actuators", "sim_assumptions"}) p.sections[k] = doc[k];
  return p;
}

// Heave force and pitch moment of the simulator at a steady state (q = 0),
// without restoring and propeller: what the balance's hydrodynamic side is.
Eigen::Vector2d simLoads(const sim::VehicleModel& m, double rho, double u, double w, double theta, double phi,
                         double plane_rad) {
  sim::Dynamics d(m);
  sim::StepInputs in;
  in.water_density_kgm3 = rho;
  in.actuators.plane_rad = plane_rad;
  d.setStepInputs(in);
  sim::StateVector s = sim::StateVector::Zero();
  s[sim::kU] = u;
  s[sim::kW] = w;
  s[sim::kTheta] = theta;
  s[sim::kPhi] = phi;
  const sim::ForceBreakdown b = d.breakdown(s);
  return {b.damping[1] + b.coriolis[1] + b.actuators[1], b.damping[2] + b.coriolis[2] + b.actuators[2]};
}

TEST(OneVehicleModel, SteadyLoadsAreTheSimulatorsForNominalAndDrawnTruths) {
  const nlohmann::json nominal = JsonReader::parseFile(kRes + "/sim/hugin1000_hydrodynamics.json");
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.8, 2.5), W(-0.15, 0.15), TH(-0.2, 0.2), PH(-0.3, 0.3), D(-0.3, 0.3);
  int checked = 0, munk_inside = 0;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const sim::DrawnTruth t = sim::drawTruth(seed);
    const nlohmann::json doc = seed == 0 ? nominal : sim::truthHydrodynamicsDoc(nominal, t);
    const VehicleProfile p = withCompanion(doc);
    const sim::VehicleModel m = sim::loadVehicleModel(p, doc, "truth");
    std::string why;
    const auto c = analysis::steadyHydroFromProfile(p, why);
    ASSERT_TRUE(c) << why;
    munk_inside += c->munk_factor == 0.0;
    for (int k = 0; k < 20; ++k) {
      const double u = U(rng), w = W(rng), th = TH(rng), ph = PH(rng), delta = D(rng), rho = 1020 + 10 * W(rng);
      const Eigen::Vector2d sim = simLoads(m, rho, u, w, th, ph, delta);
      // The log's elevator is trailing edge down positive = minus the paper's deflection.
      const analysis::SteadyFlight f{u, th, ph, -units::radToDeg(delta), w * std::cos(th) * std::cos(ph) - u * std::sin(th), rho};
      const analysis::HydroLoads h = analysis::steadyHydroLoads(*c, f);
      EXPECT_NEAR(h.Z(), sim[0], 1e-9 * (1 + std::abs(sim[0]))) << t.describe();
      EXPECT_NEAR(h.M(), sim[1], 1e-9 * (1 + std::abs(sim[1]))) << t.describe();
      ++checked;
    }
  }
  EXPECT_EQ(checked, 240);
  EXPECT_GT(munk_inside, 0);  // both structures were exercised
}

TEST(OneVehicleModel, CalibratedCoefficientsReproduceTheGroupsTheyWereGiven) {
  // The calibration's parameter vector set to a drawn truth's groups gives
  // that truth's steady loads (Munk moment carried inside M_w).
  const nlohmann::json nominal = JsonReader::parseFile(kRes + "/sim/hugin1000_hydrodynamics.json");
  const sim::DrawnTruth t = sim::drawTruth(5);
  std::string why;
  const auto c0 = analysis::steadyHydroFromProfile(withCompanion(nominal), why);
  const auto ct = analysis::steadyHydroFromProfile(withCompanion(sim::truthHydrodynamicsDoc(nominal, t)), why);
  ASSERT_TRUE(c0 && ct);
  const double rho = 1025.0;
  Eigen::VectorXd p = Eigen::VectorXd::Zero(analysis::kCalibrationCount);
  p(analysis::kHeave) = t.heave_scale;
  p(analysis::kPitchUw) = analysis::pitchMomentUw(*ct, rho, ct->munk_factor);
  p(analysis::kCrossflow) = t.crossflow_scale;
  p(analysis::kPlanes) = t.plane_scale;
  const analysis::SteadyHydroCoefficients k = analysis::calibratedCoefficients(*c0, rho, p);
  const analysis::SteadyFlight f{2.0, -0.02, 0.05, 3.0, 0.01, rho};
  EXPECT_NEAR(analysis::steadyHydroLoads(k, f).Z(), analysis::steadyHydroLoads(*ct, f).Z(), 1e-9);
  EXPECT_NEAR(analysis::steadyHydroLoads(k, f).M(), analysis::steadyHydroLoads(*ct, f).M(), 1e-9);
}

TEST(TruthDraw, IsDeterministicAndInsideTheIssuesRanges) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const sim::DrawnTruth a = sim::drawTruth(seed), b = sim::drawTruth(seed);
    EXPECT_EQ(a.describe(), b.describe());
    EXPECT_GE(a.heave_scale, 0.6);
    EXPECT_LE(a.heave_scale, 1.4);
    EXPECT_GE(a.plane_scale, 0.6);
    EXPECT_LE(a.plane_scale, 1.2);
    EXPECT_GE(a.torque_factor, 0.0);
    EXPECT_LE(a.torque_factor, 2.0);
    EXPECT_GE(a.bg_m, 0.012);
    EXPECT_LE(a.bg_m, 0.030);
    EXPECT_LE(std::abs(a.cg_x_m), 0.025);
    EXPECT_LE(std::abs(a.cg_y_m), 0.003);
    EXPECT_GE(a.net_buoyancy_kg, 1.0);
    EXPECT_LE(a.net_buoyancy_kg, 8.0);
  }
  EXPECT_NE(sim::drawTruth(1).describe(), sim::drawTruth(2).describe());
}

}  // namespace
}  // namespace auv

namespace auv {
namespace {

// The manoeuvre's predicted sigma (item 5) is the posterior of the same
// model: calibrating the log plus the planned segments, measured exactly as
// predicted, gives the covariance covarianceAfter() promised.
TEST(CalibrationManoeuvre, PredictedCovarianceIsTheCalibrationWithThePlannedLegs) {
  const nlohmann::json nominal = JsonReader::parseFile(std::string(AUV_RESOURCE_DIR) + "/sim/hugin1000_hydrodynamics.json");
  VehicleProfile p = loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/hugin1000.json");
  for (const char* k : {"hydrodynamics", "actuators"}) p.sections[k] = nominal[k];
  std::string why;
  const auto c = analysis::steadyHydroFromProfile(p, why);
  ASSERT_TRUE(c);
  const double W = 1500.0 * units::g0, rho = 1025.0;
  // Two legs at one speed and depth: weakly identified.
  auto seg = [](double u, double th, double e) {
    analysis::CalibrationSegment s;
    s.v = {u, th, 0.0, e, 0.0};
    s.se = {0.002, 2e-4, 2e-4, 0.02, 0.001};
    return s;
  };
  const std::vector<analysis::CalibrationSegment> log = {seg(2.0, -0.010, 2.0), seg(2.0, -0.011, 2.1)};
  // The Fisher prediction cannot know how the legs will scatter: compared
  // without the narrowing to their scatter (noise-free legs here).
  analysis::CalibrationPriors pri;
  pri.narrow_to_scatter = false;
  const analysis::SteadyCalibration cal = analysis::calibrateSteady(*c, W, rho, log, pri);
  ASSERT_TRUE(cal.ok);
  // Planned legs at the values the calibrated model predicts for them: the
  // residuals there are zero, so adding them moves only the covariance.
  const analysis::SteadyHydroCoefficients k = analysis::calibratedCoefficients(*c, rho, cal.p);
  std::vector<analysis::CalibrationSegment> planned;
  for (double u : {1.5, 2.5}) {
    // Solve heave and pitch for (theta, e) at the calibrated state by Newton on the same balance.
    double th = 0.0, e = 0.0;
    for (int it = 0; it < 50; ++it) {
      auto r = [&](double t, double el) {
        const analysis::HydroLoads h = analysis::steadyHydroLoads(k, {u, t, 0.0, el - cal.elevator_offset_deg, 0.0, rho});
        return Eigen::Vector2d(cal.p(analysis::kNet) * std::cos(t) - h.Z(),
                               W * (cal.p(analysis::kBg) * std::sin(t) + cal.p(analysis::kXg) * std::cos(t)) - h.M());
      };
      const Eigen::Vector2d f = r(th, e);
      Eigen::Matrix2d J;
      J.col(0) = (r(th + 1e-7, e) - f) / 1e-7;
      J.col(1) = (r(th, e + 1e-7) - f) / 1e-7;
      const Eigen::Vector2d d = J.inverse() * (-f);
      th += d(0), e += d(1);
    }
    planned.push_back(seg(u, th, e));
  }
  const Eigen::MatrixXd predicted = analysis::covarianceAfter(*c, W, rho, cal, planned);
  std::vector<analysis::CalibrationSegment> all = log;
  all.insert(all.end(), planned.begin(), planned.end());
  const analysis::SteadyCalibration after = analysis::calibrateSteady(*c, W, rho, all, pri);
  ASSERT_TRUE(after.ok);
  const double s_pred = std::sqrt(predicted(analysis::kNet, analysis::kNet));
  const double s_after = std::sqrt(after.cov(analysis::kNet, analysis::kNet));
  EXPECT_LT(s_pred, 0.7 * std::sqrt(cal.cov(analysis::kNet, analysis::kNet)));  // the legs help
  EXPECT_NEAR(s_pred, s_after, 0.05 * s_after);
  EXPECT_NEAR(std::sqrt(predicted(analysis::kXg, analysis::kXg)), std::sqrt(after.cov(analysis::kXg, analysis::kXg)),
              0.05 * std::sqrt(after.cov(analysis::kXg, analysis::kXg)));
}

}  // namespace
}  // namespace auv
