#include "weighing/tank_weighing_file.h"

#include <gtest/gtest.h>

#include <string>

#include "common/input_error.h"
#include "slocum_test_support.h"

namespace auv {
namespace {

const std::string kExample = std::string(AUV_RESOURCE_DIR) + "/examples/slocum_tank_weighing.json";

const char* kMinimal = R"({
  "dry_mass_kg": 50.0,
  "ballast_g": { "fore_port": 60, "fore_starboard": 30, "aft_upper": 293, "aft_lower": 0 },
  "tank": { "temperature_degC": 18, "bow_scale_g": 550, "aft_scale_g": 490 },
  "target": { "density_kgm3": 1025, "temperature_degC": 3 }
})";

// Replaces the first occurrence of `from` in the minimal file.
std::string edited(const std::string& from, const std::string& to) {
  std::string s = kMinimal;
  s.replace(s.find(from), from.size(), to);
  return s;
}

InputError errorOf(const std::string& json) {
  try {
    parseTankWeighing(json, "session.json");
  } catch (const InputError& e) {
    return e;
  }
  return InputError("none", "no error", "");
}

}  // namespace

TEST(TankWeighingFile, ExampleHoldsTheAppendixBSession) {
  const TankWeighing w = loadTankWeighing(kExample);
  EXPECT_EQ(w.vehicle, "slocum_g2");
  EXPECT_EQ(w.glider, "49");
  EXPECT_DOUBLE_EQ(w.readings.dry_mass_kg, 52.2);
  EXPECT_DOUBLE_EQ(w.readings.bow_scale_kg, 0.650);
  EXPECT_DOUBLE_EQ(w.readings.aft_scale_kg, 0.520);
  EXPECT_DOUBLE_EQ(w.readings.tank.density_kgm3, 1000.0);
  EXPECT_DOUBLE_EQ(w.readings.tank.temperature_degC, 18.5);
  EXPECT_DOUBLE_EQ(w.readings.target.density_kgm3, 1026.0);
  EXPECT_DOUBLE_EQ(w.readings.target.temperature_degC, 3.5);
  EXPECT_DOUBLE_EQ(w.ballast.at(kForePort), 0.208);
  EXPECT_DOUBLE_EQ(w.ballast.at(kForeStarboard), 0.110);
  EXPECT_DOUBLE_EQ(w.ballast.at(kAftUpper), 0.200);
  EXPECT_DOUBLE_EQ(w.ballast.at(kAftLower), 0.260);
  EXPECT_DOUBLE_EQ(w.ballast.at(kRailPort), 0.060);
  EXPECT_DOUBLE_EQ(w.ballast.disks[0].top_kg, 0.550);
  EXPECT_DOUBLE_EQ(w.ballast.disks[1].bottom_kg, 0.555);
  EXPECT_DOUBLE_EQ(w.ballast.disks[2].top_kg, 0.555);
  ASSERT_TRUE(w.battery_mass_kg.has_value());
  EXPECT_DOUBLE_EQ(*w.battery_mass_kg, 7.86);
  ASSERT_TRUE(w.bottles_after_tank_step_kg.has_value());
  EXPECT_DOUBLE_EQ((*w.bottles_after_tank_step_kg)[kAftUpper], 0.288);
  ASSERT_TRUE(w.roll_test.has_value());
  const RollTest t = w.roll_test->resolve(0.2);
  EXPECT_DOUBLE_EQ(t.initial_roll_rad, 0.09);
  ASSERT_EQ(t.applied.size(), 3u);
  EXPECT_DOUBLE_EQ(t.applied[2].mass_kg, 0.7);
  EXPECT_DOUBLE_EQ(t.applied[2].y_m, -0.1065);  // port rail, the file's lever arm (not the 0.2 default)
  EXPECT_DOUBLE_EQ(t.applied[2].roll_rad, -0.16);
}

TEST(TankWeighingFile, MinimalFileUsesDocumentedDefaults) {
  const TankWeighing w = parseTankWeighing(kMinimal, "session.json");
  EXPECT_DOUBLE_EQ(w.readings.tank.density_kgm3, kFreshTankDensityKgm3);  // "water" defaults to fresh
  EXPECT_DOUBLE_EQ(w.readings.target_pressure_dbar, 0.0);
  EXPECT_DOUBLE_EQ(w.ballast.at(kRailStarboard), 0.0);
  EXPECT_DOUBLE_EQ(w.ballast.battery_angle_rad, 0.0);
  EXPECT_FALSE(w.battery_mass_kg.has_value());
  EXPECT_FALSE(w.roll_test.has_value());
  EXPECT_FALSE(w.bottles_after_tank_step_kg.has_value());
  // Without a lever arm in the file the caller's default (the hull radius) is used.
  RollTestRecord rec;
  rec.applied.push_back({0.5, true, 0.1});
  EXPECT_DOUBLE_EQ(rec.resolve(0.1065).applied[0].y_m, 0.1065);
}

TEST(TankWeighingFile, ErrorsNameTheFileAndField) {
  InputError e = errorOf(edited("\"bow_scale_g\": 550, ", ""));
  EXPECT_EQ(e.field(), "tank.bow_scale_g");
  EXPECT_EQ(e.where().file, "session.json");
  EXPECT_NE(std::string(e.what()).find("missing required field"), std::string::npos);

  EXPECT_EQ(errorOf(edited("\"aft_upper\": 293", "\"aft_upper\": \"293\"")).field(), "ballast_g.aft_upper");
  EXPECT_EQ(errorOf(edited("\"density_kgm3\": 1025", "\"density_kgm3\": 1.025")).field(), "target.density_kgm3");
  EXPECT_EQ(errorOf(edited("\"temperature_degC\": 18,", "\"water\": \"salt\", \"temperature_degC\": 18,")).field(),
            "tank.density_kgm3");
  EXPECT_EQ(errorOf(edited("\"temperature_degC\": 18,", "\"water\": \"brackish\", \"temperature_degC\": 18,")).field(),
            "tank.water");
  EXPECT_EQ(errorOf(edited("\"dry_mass_kg\": 50.0,", "\"method\": \"crane\", \"dry_mass_kg\": 50.0,")).field(),
            "method");
  e = errorOf(edited("\"temperature_degC\": 3", "\"temperature_degC\": 3, \"pressure\": 100"));
  EXPECT_EQ(e.field(), "target.pressure");
  EXPECT_NE(std::string(e.what()).find("pressure_dbar"), std::string::npos);  // the fix lists the right name
  const std::string roll = R"(, "roll_test": { "initial_roll_rad": 0.09, "applied": [
      { "mass_kg": 0.3, "rail": "port", "roll_rad": -0.12 }, { "mass_kg": 0.4, "rail": "left", "roll_rad": -0.15 } ] } })";
  std::string s = kMinimal;
  s.replace(s.rfind('}'), 1, roll);
  EXPECT_EQ(errorOf(s).field(), "roll_test.applied[1].rail");
}

TEST(TankWeighingFile, SyntaxErrorsCarryLineAndColumn) {
  const InputError e = errorOf(edited("\"aft_lower\": 0 }", "\"aft_lower\": 0, }"));
  EXPECT_EQ(e.where().line, 3);
  EXPECT_GT(e.where().column, 0);
}

TEST(SlocumLayout, ShippedProfileHoldsTheReportGeometry) {
  const VehicleProfile v = slocum_test::profile();
  EXPECT_EQ(v.kind, "glider");
  EXPECT_DOUBLE_EQ(v.hull.thermal_expansion_per_degC, 7e-5);
  const SlocumLayout L = slocumLayout(v);
  EXPECT_DOUBLE_EQ(L.hull_radius_m, 0.1065);
  EXPECT_NEAR(L.target_h_arm_m, 0.006, 1e-15);
  EXPECT_DOUBLE_EQ(L.battery.radius_m, 0.0635);
  EXPECT_DOUBLE_EQ(L.battery.max_angle_rad, 0.288);
  EXPECT_DOUBLE_EQ(L.mass_resolution_kg, 0.001);
  // Report: bow bottles at r = 74.9 mm, delta = -0.975 rad below the horizontal.
  EXPECT_NEAR(L.item(kForeStarboard).position_m.y(), 0.0749 * std::cos(0.975), 5e-6);
  EXPECT_NEAR(L.item(kForeStarboard).position_m.z(), 0.0749 * std::sin(0.975), 5e-6);
  EXPECT_NEAR(L.item(kAftUpper).position_m.z(), -0.072, 1e-15);
  EXPECT_NEAR(L.item(kAftLower).position_m.z(), 0.058, 1e-15);
  EXPECT_NEAR(L.item(kRailStarboard).position_m.y(), 0.11, 1e-15);
  for (int i = 0; i <= kAftLower; ++i) EXPECT_DOUBLE_EQ(L.items[static_cast<std::size_t>(i)].capacity_kg, 0.45);
  EXPECT_DOUBLE_EQ(L.item(kRailPort).capacity_kg, 0.12);
  EXPECT_NEAR(L.disks[1].bottom_z_m, 0.07, 1e-15);
}

TEST(SlocumLayout, DisagreementWithTheAdjustmentPointsIsNamed) {
  VehicleProfile v = slocum_test::profile();
  v.sections["slocum"]["ballast_bottles"]["aft_upper"]["capacity_kg"] = 0.5;
  try {
    slocumLayout(v);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "slocum.ballast_bottles.aft_upper");
    EXPECT_NE(e.where().file.find("slocum_g2.json"), std::string::npos);
  }
  v = slocum_test::profile();
  v.sections["slocum"]["roll_battery"].erase("radius_m");
  try {
    slocumLayout(v);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "slocum.roll_battery.radius_m");
  }
  v.sections.erase("slocum");
  try {
    slocumLayout(v);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "slocum");
  }
}

}  // namespace auv
