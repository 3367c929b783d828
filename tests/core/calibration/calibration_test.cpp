// One vehicle model (issue 11 item 1): the steady heave force and pitch
// moment the analysis inverts are the simulator's, term by term, for the
// nominal vehicle and for truths drawn away from it (Munk moment on top of
// M_w or inside it). The oracle is sim::Dynamics::breakdown, the function
// the integrator calls.
#include <gtest/gtest.h>

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
