// Glider steady-glide calibration on synthetic yos with a known hull volume:
// the fitted net buoyancy and the ballast to add must match the truth
// evaluated at the analysis's own reference state.
#include <gtest/gtest.h>

#include "analysis/glider_flight.h"
#include "analysis/mission_analysis.h"
#include "glider_truth.h"
#include "vehicle/vehicle_catalog.h"

using namespace auv;
using namespace auv::analysis;
using namespace auv::analysis::test;

namespace {

VehicleProfile slocum() { return VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("slocum_g2"); }

GliderTruth truthWithNetBuoyancyAt75m(double nb_kg) {
  GliderTruth g;
  const double z = 75.0, p = seawater::pressureFromDepth(z);
  const double f = (1 - g.kappa_per_dbar * p) * (1 + g.alpha_per_degC * (waterT(z) - g.T0_degC));
  g.V0_m3 = (g.mass_kg + nb_kg) / (waterRho(z) * f);
  return g;
}

// rho V(p, T) - m at the reference state the analysis reports.
double truthAtReference(const GliderTruth& g, const nlohmann::json& ref, double rho) {
  const double p = ref["pressure_dbar"].get<double>(), T = ref["temperature_degC"].get<double>();
  return rho * g.V0_m3 * (1 - g.kappa_per_dbar * p) * (1 + g.alpha_per_degC * (T - g.T0_degC)) - g.mass_kg;
}

}  // namespace

TEST(GliderFlightModel, AngleOfAttackSolvesTheGlideEquation) {
  GliderFlightConstants c;
  for (double pitch_deg : {-40.0, -26.0, -15.0, 12.0, 24.0, 45.0}) {
    const double th = units::degToRad(pitch_deg);
    const double a = steadyAngleOfAttack(c, th, 0.15);
    EXPECT_EQ(std::signbit(a), std::signbit(th));
    // gliderflight's implicit equation: alpha = (Cd0 + Cd1 alpha^2) / (a tan(alpha + theta)).
    EXPECT_NEAR(std::abs(a), (0.15 + 10.5 * a * a) / (7.53 * std::tan(std::abs(a + th))), 1e-10);
    EXPECT_LT(std::abs(a), units::degToRad(10));
  }
}

TEST(GliderFlightModel, VerticalSpeedMatchesTheForceBalance) {
  // At a state with F_B known, lift and drag from the returned speed balance it.
  GliderFlightConstants c;
  c.mass_kg = 52.2;
  c.compressibility_per_dbar = 0;
  const ReferenceState ref{1025.0, 0.0, 20.0};
  GlideSample s;
  s.pitch_rad = units::degToRad(-25.0);
  s.density_kgm3 = 1025.0;
  s.temperature_degC = 20.0;
  s.pump_m3 = -200e-6;
  const double nb = 0.05;
  const double w = steadyGlideVerticalSpeed(c, ref, nb, 0.15, s);
  const double FB = units::g0 * (1025.0 * ((c.mass_kg + nb) / 1025.0 + s.pump_m3) - c.mass_kg);  // -1.52 N
  const double alpha = steadyAngleOfAttack(c, s.pitch_rad, 0.15);
  const double gamma = s.pitch_rad + alpha;
  const double U = w / std::sin(gamma);
  const double q = 0.5 * 1025.0 * U * U * c.wing_area_m2;
  const double L = q * c.lift_slope_per_rad * alpha, D = q * (0.15 + c.induced_drag_per_rad2 * alpha * alpha);
  // Along and across the path (gliderflight's dynamic-model force components, zero in steady state).
  EXPECT_NEAR(-std::cos(gamma) * D + std::sin(gamma) * L, 0.0, 1e-9);
  EXPECT_NEAR(-std::cos(gamma) * L - std::sin(gamma) * D + FB, 0.0, 1e-9);
  EXPECT_LT(w, -0.1);
}

TEST(GliderSyntheticTruth, RecoversNetBuoyancyAndBallastToAdd) {
  const VehicleProfile v = slocum();
  for (double nb : {0.06, -0.05}) {
    GliderTruth g = truthWithNetBuoyancyAt75m(nb);
    AnalysisOptions o;
    o.target_density_kgm3 = 1026.0;
    const AnalysisReport r = analyzeMission(makeGliderLog(g), v, o);
    SCOPED_TRACE("nb " + std::to_string(nb));
    ASSERT_TRUE(r.net_buoyancy_kg.known) << r.net_buoyancy_kg.why_not;
    const auto& d = r.details["glider_fit"];
    const double rho_ref = d["reference"]["density_kgm3"].get<double>();
    const double truth = truthAtReference(g, d["reference"], rho_ref);
    EXPECT_NEAR(r.net_buoyancy_kg.value, truth, 0.010);
    EXPECT_NEAR(r.net_buoyancy_kg.value, truth, 3 * r.net_buoyancy_kg.sigma + 0.002);
    EXPECT_LT(r.net_buoyancy_kg.sigma, 0.02);
    EXPECT_NEAR(d["Cd0"].get<double>(), 0.15, 0.02);
    const double add_truth = 1000 * truthAtReference(g, d["reference"], 1026.0);
    EXPECT_NEAR(r.mass_to_add_g.value, add_truth, 12.0);
    EXPECT_EQ(r.target_density_kgm3, 1026.0);
    // 8 dives and 8 climbs used.
    int glides = 0;
    for (const auto& s : r.segments) glides += s.used;
    EXPECT_EQ(glides, 16);
    const nlohmann::json j = toJson(r);
    EXPECT_TRUE(j["mass_to_add_g"].is_number());
    EXPECT_TRUE(j["mass_to_add_sigma_g"].is_number());
    EXPECT_TRUE(j["cg_offset_mm"]["x"].is_null());
  }
}

TEST(GliderSyntheticTruth, DefaultTargetIsTheMeanDensityBelow10m) {
  GliderTruth g = truthWithNetBuoyancyAt75m(0.03);
  const AnalysisReport r = analyzeMission(makeGliderLog(g), slocum(), {});
  ASSERT_TRUE(r.mass_to_add_g.known);
  EXPECT_EQ(r.target_density_kgm3, r.density_kgm3.mean);
  // At the operating density the ballast to add is the net buoyancy itself.
  EXPECT_NEAR(r.mass_to_add_g.value, 1000 * r.net_buoyancy_kg.value, 1e-9);
  EXPECT_GT(r.density_kgm3.mean, waterRho(10.0));
  EXPECT_LT(r.density_kgm3.mean, waterRho(150.0));
}

TEST(GliderSyntheticTruth, NoPumpChannelIsNotIdentifiable) {
  GliderTruth g = truthWithNetBuoyancyAt75m(0.03);
  g.log_pump = false;
  const AnalysisReport r = analyzeMission(makeGliderLog(g), slocum(), {});
  EXPECT_FALSE(r.net_buoyancy_kg.known);
  EXPECT_NE(r.net_buoyancy_kg.why_not.find("pump_volume"), std::string::npos);
  EXPECT_TRUE(toJson(r)["mass_to_add_g"].is_null());
}
