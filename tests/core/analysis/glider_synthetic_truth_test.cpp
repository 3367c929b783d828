// Glider steady-glide calibration on synthetic yos with a known hull volume:
// the fitted net buoyancy and the ballast to add must match the truth
// evaluated at the analysis's own reference state.
#include <gtest/gtest.h>

#include "analysis/glider_flight.h"
#include "analysis/glider_target.h"
#include "common/input_error.h"
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
    // Only the density was given: p and T of the target are the log's own
    // water at the bottom of its deepest yo (150 m).
    EXPECT_EQ(r.target_density_kgm3, 1026.0);
    EXPECT_NEAR(r.target_pressure_dbar, seawater::pressureFromDepth(150.0), 4.0);
    EXPECT_NEAR(r.target_temperature_degC, waterT(150.0), 0.05);
    const nlohmann::json target = {{"pressure_dbar", r.target_pressure_dbar}, {"temperature_degC", r.target_temperature_degC}};
    const double add_truth = 1000 * truthAtReference(g, target, 1026.0);
    EXPECT_NEAR(r.mass_to_add_g.value, add_truth, 12.0);
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

TEST(GliderSyntheticTruth, DefaultTargetIsTheWaterAtTheBottomOfTheDeepestYo) {
  GliderTruth g = truthWithNetBuoyancyAt75m(0.03);
  const AnalysisReport r = analyzeMission(makeGliderLog(g), slocum(), {});
  ASSERT_TRUE(r.mass_to_add_g.known);
  // The yos reach 150 m; the CTD there (within 5 m of the deepest point).
  EXPECT_NEAR(r.target_pressure_dbar, seawater::pressureFromDepth(150.0), 4.0);
  EXPECT_NEAR(r.target_temperature_degC, waterT(150.0), 0.05);
  EXPECT_NEAR(r.target_density_kgm3, waterRho(150.0), 0.03);
  EXPECT_NE(r.target_basis.find("deepest yo"), std::string::npos) << r.target_basis;
  // Neutral there with the pump at zero: the truth's rho V(p, T) - m.
  const nlohmann::json target = {{"pressure_dbar", r.target_pressure_dbar}, {"temperature_degC", r.target_temperature_degC}};
  EXPECT_NEAR(r.mass_to_add_g.value, 1000 * truthAtReference(g, target, r.target_density_kgm3), 10.0);
  // Deeper and colder than the mean operating water: more to add than the net buoyancy there.
  EXPECT_GT(r.mass_to_add_g.value, 1000 * r.net_buoyancy_kg.value);
  const nlohmann::json j = toJson(r);
  EXPECT_NEAR(j["target"]["density_kgm3"].get<double>(), r.target_density_kgm3, 1e-5);  // the report rounds
  EXPECT_NEAR(j["target"]["pressure_dbar"].get<double>(), r.target_pressure_dbar, 1e-5);
  EXPECT_NEAR(j["target"]["temperature_degC"].get<double>(), r.target_temperature_degC, 1e-5);
}

TEST(GliderSyntheticTruth, TargetDepthTakesTheLogsOwnProfileAndRefusesDepthsNotReached) {
  GliderTruth g = truthWithNetBuoyancyAt75m(0.03);
  const MissionLog log = makeGliderLog(g);
  GliderTargetRequest q;
  q.depth_m = 60.0;
  const GliderTarget t = resolveGliderTarget(log, q, 45.0);
  EXPECT_NEAR(t.temperature_degC, waterT(60.0), 0.03);
  EXPECT_NEAR(t.pressure_dbar, seawater::pressureFromDepth(60.0, 45.0), 1e-9);
  EXPECT_NEAR(t.density_kgm3, waterRho(60.0), 0.02);
  q.depth_m = 400.0;
  try {
    resolveGliderTarget(log, q, 45.0);
    ADD_FAILURE() << "a depth the log never reached must be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "target-depth");
  }
  // All three given: used as they are, whatever the log holds.
  const GliderTarget given = resolveGliderTarget(log, {1027.9, 500.0, 4.0, std::nullopt}, 45.0);
  EXPECT_EQ(given.density_kgm3, 1027.9);
  EXPECT_EQ(given.pressure_dbar, 500.0);
  EXPECT_EQ(given.temperature_degC, 4.0);
}

TEST(GliderFlightModel, MassToAddCarriesTheVolumeToTheTarget) {
  // 0.05 m3 at 0 dbar, 20 degC; kappa 4e-6/dbar, alpha 7e-5/degC: at 500 dbar
  // and 5 degC the volume is 0.05 (1 - 0.002)(1 - 0.00105) = 0.04984758 m3.
  GliderTarget t{1027.0, 500.0, 5.0, 35.0, ""};
  EXPECT_NEAR(gliderMassToAddKg(0.05, 4e-6, 7e-5, 20.0, t, 51.0), 1027.0 * 0.05 * 0.998 * 0.99895 - 51.0, 1e-12);
}

TEST(GliderFlightModel, SeagliderFormBalancesLiftDragAndBuoyancy) {
  // Eriksen et al. 2001: lift = hd_a alpha q l^2, drag = (hd_b q^s + hd_c alpha^2) q l^2 with
  // alpha in degrees; steady flight: lift = B cos(glide), drag = B sin(glide).
  GliderFlightConstants c;
  c.form = GlideForm::kSeaglider;
  c.hd_a_per_deg = 0.0036;
  c.hd_c_per_deg2 = 5.7e-6;
  c.hd_s = -0.25;
  c.hull_length_m = 1.8;
  c.rho0_kgm3 = 1027.5;
  const double hd_b = 0.0106;
  for (double pitch_deg : {-25.0, -16.0, 18.0, 30.0}) {
    const double B = std::copysign(1.5, pitch_deg);  // N, the sign of the pitch
    const double w = seagliderVerticalSpeed(c, B, units::degToRad(pitch_deg), hd_b);
    ASSERT_NE(w, 0.0);
    EXPECT_EQ(std::signbit(w), std::signbit(pitch_deg));
    // Recover U and the glide angle from w by the lift/drag balance and check both equations.
    const double l2 = 1.8 * 1.8;
    double best = 1e9;
    for (double g = std::abs(pitch_deg) + 0.01; g < 89.0; g += 0.001) {
      const double U = std::abs(w) / std::sin(units::degToRad(g));
      const double q = 0.5 * 1027.5 * U * U;
      const double alpha = g - std::abs(pitch_deg);
      const double L = c.hd_a_per_deg * alpha * q * l2;
      const double D = (hd_b * std::pow(q, c.hd_s) + c.hd_c_per_deg2 * alpha * alpha) * q * l2;
      best = std::min(best, std::hypot(L - 1.5 * std::cos(units::degToRad(g)), D - 1.5 * std::sin(units::degToRad(g))));
    }
    EXPECT_LT(best, 2e-3) << pitch_deg;
  }
  EXPECT_EQ(seagliderVerticalSpeed(c, 1.5, units::degToRad(-20.0), hd_b), 0.0) << "buoyant but pitched down: stalled";
}

TEST(GliderSyntheticTruth, NoPumpChannelIsNotIdentifiable) {
  GliderTruth g = truthWithNetBuoyancyAt75m(0.03);
  g.log_pump = false;
  const AnalysisReport r = analyzeMission(makeGliderLog(g), slocum(), {});
  EXPECT_FALSE(r.net_buoyancy_kg.known);
  EXPECT_NE(r.net_buoyancy_kg.why_not.find("pump_volume"), std::string::npos);
  EXPECT_TRUE(toJson(r)["mass_to_add_g"].is_null());
}
