// Where a glider's grams go (planning/glider_ballast_plan.h). Oracles: the
// moment balance about the CB for the Slocum bottles (Baird 2007's level
// split plus the battery moment the pitch trim asks for), the roll-moment
// balance for the wing rails, and for the Seaglider the conservation of
// weight in water (VBD volume and lead together must remove exactly the
// buoyancy excess) with basestation's constants.
#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.h"
#include "planning/glider_ballast_plan.h"
#include "seawater/seawater.h"
#include "vehicle/vehicle_catalog.h"

using namespace auv;

namespace {

VehicleProfile load(const char* id) { return VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load(id); }

nlohmann::json report(double add_g, double rho, double level_mm, double roll_deg) {
  // tan(pitch) = T1 pump + T2 battery + T3, level at pump 0 for battery = level_mm.
  const double T2 = -0.02;
  return {{"mass_to_add_g", add_g},
          {"mass_to_add_sigma_g", 3.0},
          {"target", {{"density_kgm3", rho}, {"pressure_dbar", 200.0}, {"temperature_degC", 8.0}, {"basis", "test"}}},
          {"details",
           {{"glider_trim",
             {{"pitch", {{"T1_per_cm3", 0.001}, {"T2_per_mm", T2}, {"T3", -T2 * level_mm}}},
              {"roll", {{"roll_deg", roll_deg}}}}}}}};
}

double addOf(const nlohmann::json& plan, const std::string& name) {
  for (const auto& p : plan["points"])
    if (p["name"] == name) return p["add_g"].get<double>();
  return NAN;
}

}  // namespace

TEST(GliderBallastPlan, SlocumBottlesCarryTheMassAndThePitchMoment) {
  const VehicleProfile v = load("slocum_g2");
  // Half-full bottles (225 g each), rails 60 g each.
  const std::vector<double> installed = {0.225, 0.225, 0.225, 0.225, 0.06, 0.06};
  const nlohmann::json plan = planGliderBallast(v, {report(100.4, 1026.0, 5.0, 1.0), installed, std::nullopt});
  EXPECT_EQ(plan["vehicle_type"], "slocum");
  const double bow = addOf(plan, "fore_port") + addOf(plan, "fore_starboard");
  const double aft = addOf(plan, "aft_upper") + addOf(plan, "aft_lower");
  // Total rounded down to whole grams (never ending heavy).
  EXPECT_EQ(bow + aft, 100.0);
  // Moment about the CB (bottles at +-500 mm): the 9 kg pitch battery sits
  // 5 mm forward for level flight, so 9 kg * 5 mm = 45 g m must move into the
  // bottles: 0.5 bow - 0.5 aft = 45 g m; and bow + aft = 100 g.
  EXPECT_NEAR(0.5 * bow - 0.5 * aft, 45.0, 0.5);
  // Roll 1 deg starboard down: m bg sin(roll) = 52.2 kg * 6 mm * sin 1 deg = 5.466 g m over
  // the 220 mm between the rails = 24.8 g from starboard to port.
  EXPECT_EQ(addOf(plan, "wing_rail_port"), 25.0);
  EXPECT_EQ(addOf(plan, "wing_rail_starboard"), -25.0);
  EXPECT_TRUE(plan["warnings"].empty()) << plan["warnings"].dump();
}

TEST(GliderBallastPlan, SlocumBottlesRespectCapacities) {
  const VehicleProfile v = load("slocum_g2");
  // Bow bottles nearly full: the bow cannot take its share.
  const std::vector<double> installed = {0.44, 0.44, 0.1, 0.1, 0.06, 0.06};
  const nlohmann::json plan = planGliderBallast(v, {report(300.0, 1026.0, 0.0, 0.0), installed, std::nullopt});
  EXPECT_LE(addOf(plan, "fore_port") + addOf(plan, "fore_starboard"), 20.0);
  for (const auto& p : plan["points"]) EXPECT_LE(p["after_g"].get<double>(), p["capacity_g"].get<double>());
  EXPECT_FALSE(plan["warnings"].empty());
}

TEST(GliderBallastPlan, SeagliderVbdAndLeadRemoveExactlyTheExcess) {
  const VehicleProfile v = load("seaglider");
  // +151.48 g at 1029.27 kg/m3: the VBD takes 151.48 / 1.02927 = 147.17 cm3,
  // 147.17 / 0.2453 = 600 counts more than C_VBD 2680.
  nlohmann::json plan = planGliderBallast(v, {report(151.48, 1029.27, 0.0, 0.0), {}, std::nullopt});
  EXPECT_EQ(plan["seaglider"]["C_VBD_new"].get<double>(), 3280.0);
  EXPECT_EQ(plan["seaglider"]["lead_change_g"].get<double>(), 0.0);
  // +1 kg: beyond VBD_MAX less the 150 cm3 margin, so lead takes the rest.
  plan = planGliderBallast(v, {report(1000.0, 1029.27, 0.0, 0.0), {}, std::nullopt});
  const auto& s = plan["seaglider"];
  const double lead_kg = s["lead_change_g"].get<double>() / 1000.0;
  const double dV_m3 = s["VBD_change_cm3"].get<double>() * 1e-6;
  EXPECT_GT(lead_kg, 0.5);
  EXPECT_NEAR(s["C_VBD_new"].get<double>(), 3960.0 - 150.0 / 0.2453, 1.0);
  // Weight in water removed: lead minus its displaced water, minus the VBD volume's buoyancy.
  EXPECT_NEAR(lead_kg - 1029.27 * (lead_kg / 11296.0) - 1029.27 * dV_m3, 1.0, 0.002);
  // Level pitch at the new VBD zero: T1 dV + T2 b + T3 = 0 with b = -(AD - C_PITCH) PITCH_CNV 10.
  const double b = -(0.0 + 0.001 * s["VBD_change_cm3"].get<double>()) / -0.02;
  EXPECT_NEAR(s["C_PITCH_new"].get<double>(), std::round(2145.0 - b / (10 * 0.00313)), 0.5);
}

TEST(GliderBallastPlan, SeaExplorerSaysWhatItCannotTell) {
  VehicleProfile v = load("slocum_g2");
  v.sections.erase("slocum");
  v.sections["seaexplorer"] = nlohmann::json::object();
  const nlohmann::json plan = planGliderBallast(v, {report(80.0, 1026.0, 12.0, 0.0), {}, std::nullopt});
  EXPECT_EQ(plan["vehicle_type"], "seaexplorer");
  EXPECT_NEAR(plan["linear_battery_for_level_mm"].get<double>(), 12.0, 1e-9);
  EXPECT_GE(plan["cannot_tell"].size(), 2u);
}

TEST(GliderBallastPlan, AnotherTargetCarriesTheFittedVolume) {
  // Report: V0 0.05 m3 at p 0 and 20 degC, kappa 4e-6, alpha 7e-5, mass 51 kg.
  nlohmann::json r = report(0.0, 1026.0, 0.0, 0.0);
  r["water"] = {{"salinity_psu", 35.0}};
  r["details"]["glider_fit"] = {{"hull_volume_m3", 0.05}, {"mass_kg", 51.0},
                                {"constants", {{"compressibility_per_dbar", 4e-6}, {"thermal_expansion_per_degC", 7e-5},
                                               {"reference_temperature_degC", 20.0}}}};
  analysis::GliderTargetRequest q;
  q.density_kgm3 = 1027.0;
  q.pressure_dbar = 500.0;
  q.temperature_degC = 5.0;
  const analysis::GliderTarget t = targetFromReport(r, q, 45.0);
  const nlohmann::json plan = planGliderBallast(load("slocum_g2"), {r, {}, t});
  EXPECT_NEAR(plan["mass_to_add_g"].get<double>(), 1000 * (1027.0 * 0.05 * (1 - 4e-6 * 500) * (1 + 7e-5 * (5.0 - 20.0)) - 51.0), 1e-6);
  // Depth only: pressure from UNESCO, density recomputed from the report's salinity.
  analysis::GliderTargetRequest d;
  d.depth_m = 300.0;
  const analysis::GliderTarget td = targetFromReport(r, d, 45.0);
  EXPECT_NEAR(seawater::depthFromPressure(td.pressure_dbar, 45.0), 300.0, 1e-3);
  EXPECT_GT(td.density_kgm3, 1026.0);
}
