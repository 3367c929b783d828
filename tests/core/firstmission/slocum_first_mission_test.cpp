#include "firstmission/slocum_first_mission.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "common/input_error.h"
#include "vehicle/profile_loader.h"
#include "weighing/tank_weighing_file.h"

namespace auv {
namespace {

const std::string kRes = AUV_RESOURCE_DIR;

VehicleProfile slocum() { return loadVehicleProfile(kRes + "/vehicles/slocum_g2.json"); }
TankWeighing appendixB() { return loadTankWeighing(kRes + "/examples/slocum_tank_weighing.json"); }

// App. B as weighed: no bottle change yet, no roll test.
TankWeighing appendixBAsWeighed() {
  TankWeighing w = appendixB();
  w.bottles_after_tank_step_kg.reset();
  w.roll_test.reset();
  return w;
}

const PointRecommendation& point(const FirstMissionReport& r, const std::string& name) {
  for (const auto& p : r.points) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no point " + name);
}

template <class Text>
bool anyContains(const std::vector<Text>& v, const std::string& s) {
  for (const auto& x : v) {
    if (x.find(s) != std::string::npos) return true;
  }
  return false;
}

std::string errorField(const VehicleProfile& v, const TankWeighing& w) {
  try {
    slocumFirstMission(v, w);
  } catch (const InputError& e) {
    return e.field();
  }
  return "no error";
}

// Neutral mass at the App. B target by hand: 51.03 kg of fresh water at
// 18.5 degC -> 0.05103 m3 * (1 - 15 * 7e-5) * 1026 kg/m3.
const double kNeutralB = 0.05103 * 0.99895 * 1026.0;  // 52.301805 kg

}  // namespace

TEST(SlocumFirstMission, AppendixBAsWeighedRecommendsTheBottleChanges) {
  const FirstMissionReport r = slocumFirstMission(slocum(), appendixBAsWeighed());
  EXPECT_EQ(r.method, "tank");
  EXPECT_EQ(r.vehicle_id, "slocum_g2");
  EXPECT_DOUBLE_EQ(r.weight_kg, 52.2);
  EXPECT_NEAR(r.buoyancy_kg, kNeutralB, 1e-12);
  EXPECT_NEAR(r.net_buoyancy_kg, kNeutralB - 52.2, 1e-12);  // +101.8 g: too light
  EXPECT_DOUBLE_EQ(r.density_kgm3, 1026.0);
  EXPECT_DOUBLE_EQ(r.temperature_degC, 3.5);
  // By hand: 101 g in (rounded down); level readings 635.5 g each -> bow
  // -14.5 -> -15 g split -8/-7, aft +116 g split +58/+58.
  EXPECT_NEAR(point(r, "fore_port").add_kg, -0.008, 1e-12);
  EXPECT_NEAR(point(r, "fore_starboard").add_kg, -0.007, 1e-12);
  EXPECT_NEAR(point(r, "aft_upper").add_kg, 0.058, 1e-12);
  EXPECT_NEAR(point(r, "aft_lower").add_kg, 0.058, 1e-12);
  EXPECT_NEAR(point(r, "wing_rail_port").add_kg, 0.0, 1e-15);
  ASSERT_EQ(point(r, "aft_upper").pieces.size(), 1u);
  EXPECT_EQ(point(r, "aft_upper").pieces[0].count, 58);
  EXPECT_DOUBLE_EQ(point(r, "aft_upper").pieces[0].size_kg, 0.001);
  EXPECT_EQ(point(r, "fore_port").pieces[0].count, -8);
  // Never heavy: 52.301805 - 52.301 = +0.8 g.
  EXPECT_NEAR(r.predicted.net_buoyancy_kg, kNeutralB - 52.301, 1e-12);
  EXPECT_GE(r.predicted.net_buoyancy_kg, 0.0);
  // CG x from the scale moments about CB (stations +-0.5 m): before
  // (0.650 - 0.520) * 0.5 / 52.2; after (0.635 - 0.636) * 0.5 / 52.301.
  EXPECT_NEAR(r.cg_m.x(), 0.130 * 0.5 / 52.2, 1e-15);
  EXPECT_NEAR(r.predicted.cg_offset_m.x(), -0.001 * 0.5 / 52.301, 1e-15);
  // Without a roll test the CG height is the profile's 6 mm BG, so the
  // static pitch is atan2(-x, z): nose down 11.7 deg before. After, the
  // bottle changes also move G in the cross-section (bow bottles at
  // y = -+42.03, z = 61.99 mm; aft at z = -72 / +58 mm):
  EXPECT_NEAR(r.pitch_before_deg, std::atan2(-0.065 / 52.2, 0.006) * 180.0 / std::numbers::pi, 1e-9);
  const double y1 = (-0.008 * -0.04203 - 0.007 * 0.04203) / 52.301;
  const double z1 = (52.2 * 0.006 - 0.015 * 0.06199 + 0.058 * (-0.072 + 0.058)) / 52.301;
  EXPECT_NEAR(r.predicted.pitch_deg, std::atan2(0.0005 / 52.301, std::hypot(y1, z1)) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(r.predicted.cg_offset_m.y(), y1, 1e-15);
  EXPECT_TRUE(anyContains(r.notes, "No roll test"));
  EXPECT_EQ(r.details["cg_z_source"], "profile bg_mm (no roll test)");
  EXPECT_NEAR(r.details["tank"]["mass_change_g"].get<double>(), 101.8054, 5e-4);
  EXPECT_NEAR(r.details["tank"]["volume_target_m3"].get<double>(), 0.050976, 5e-7);
  EXPECT_FALSE(r.details.contains("h_arm"));
}

TEST(SlocumFirstMission, AppendixBSessionEndToEnd) {
  const VehicleProfile v = slocum();
  const FirstMissionReport r = slocumFirstMission(v, appendixB());
  // As the session set the bottles the glider weighs 52.302 kg, 0.2 g more
  // than neutral: the report accepted that, we take 1 g out first.
  EXPECT_NEAR(r.weight_kg, 52.302, 1e-12);
  EXPECT_NEAR(r.net_buoyancy_kg, kNeutralB - 52.302, 1e-12);
  EXPECT_LT(r.net_buoyancy_kg, 0.0);
  EXPECT_NEAR(r.predicted.net_buoyancy_kg, kNeutralB - 52.301, 1e-12);
  EXPECT_GE(r.predicted.net_buoyancy_kg, 0.0);
  EXPECT_EQ(r.details["state"], "after_tank_step");

  // Recommendation names are the profile's adjustment points, in order.
  ASSERT_EQ(r.points.size(), v.points.size());
  for (std::size_t i = 0; i < v.points.size(); ++i) EXPECT_EQ(r.points[i].name, v.points[i].name);
  double total = 0.0;
  for (const auto& p : r.points) total += p.add_kg;
  EXPECT_NEAR(total, -0.001, 1e-12);

  // Roll test: the printed h = 5.4528 mm; G 0.49 mm to starboard.
  EXPECT_NEAR(r.details["roll_test"]["h_mm"].get<double>(), 5.4528, 5e-5);
  EXPECT_NEAR(r.cg_m.y(), 0.0054528 * std::sin(0.09), 5e-8);
  EXPECT_NEAR(r.roll_before_deg, 0.09 * 180.0 / std::numbers::pi, 1e-9);  // measured initial roll
  // Battery alone (the report's choice), at -asin(M y_G / (m_b r_b)) with the
  // 1 g removal moving G a hair: within 1e-4 rad of App. B's -0.0513793.
  EXPECT_EQ(r.details["roll_correction"]["method"], "battery");
  EXPECT_NEAR(r.details["battery"]["angle_rad"].get<double>(), -0.0513793, 1e-4);
  EXPECT_NEAR(r.predicted.roll_deg, 0.0, 1e-9);
  // h-arm: 6 mm unreachable; best is no disk swap and 162 g down in the aft
  // bottles, about 5.82 mm (disk_weights_test has the exact App. B numbers).
  EXPECT_EQ(r.details["h_arm"]["arrangement"], 0);
  EXPECT_NEAR(r.details["h_arm"]["after_mm"].get<double>(), 5.82, 0.01);
  EXPECT_NEAR(r.details["h_arm"]["aft_shift_up_g"].get<double>(), -162.0, 1e-9);
  EXPECT_TRUE(anyContains(r.warnings, "h-arm target 6.00 mm is not reachable"));
  EXPECT_NEAR(point(r, "aft_lower").add_kg, 0.162, 1e-12);

  // Every note is one sentence.
  ASSERT_GE(r.notes.size(), 5u);
  for (const auto& n : r.notes) {
    EXPECT_EQ(n.back(), '.') << n;
  }
  EXPECT_TRUE(anyContains(r.notes, "roll battery"));

  // The shared JSON contract carries it all.
  const nlohmann::json j = toJson(r);
  EXPECT_EQ(j["method"], "tank");
  EXPECT_EQ(j["recommendation"]["points"][3]["name"], "aft_lower");
  EXPECT_NEAR(j["recommendation"]["points"][3]["add_kg"].get<double>(), 0.162, 1e-9);
  EXPECT_TRUE(j["details"].contains("battery"));
}

TEST(SlocumFirstMission, RollTestBeforeTheBottleChangeIsCarriedThroughIt) {
  // Roll test on the glider as weighed (52.2 kg): G is measured there, then
  // the planned bottle changes (-8 g port / -7 g starboard bow at y = -+42.03
  // mm, +58/+58 g aft on the axis) move its lateral moment by
  // 0.008 * 0.04203 - 0.007 * 0.04203 kg m before the battery cancels it.
  TankWeighing w = appendixB();
  w.bottles_after_tank_step_kg.reset();
  const FirstMissionReport r = slocumFirstMission(slocum(), w);
  const double h = r.details["roll_test"]["h_mm"].get<double>() / 1000.0;
  EXPECT_NEAR(r.details["roll_test"]["glider_mass_kg"].get<double>(), 52.2, 1e-12);
  const double moment_y = 52.2 * h * std::sin(0.09) + (0.008 - 0.007) * 0.04203;
  EXPECT_NEAR(r.details["battery"]["angle_rad"].get<double>(), -std::asin(moment_y / (7.86 * 0.0635)), 1e-6);
  EXPECT_NEAR(r.predicted.roll_deg, 0.0, 1e-9);
  EXPECT_EQ(r.details["state"], "as_weighed");
}

TEST(SlocumFirstMission, NeverRecommendsEndingHeavy) {
  // Sweep dry mass, readings and target density; whenever the bottles can
  // do it the predicted glider is neutral to within one gram, on the light side.
  const VehicleProfile v = slocum();
  for (int k = 0; k < 60; ++k) {
    TankWeighing w = appendixBAsWeighed();
    w.readings.dry_mass_kg = 52.0 + 0.00731 * k;
    w.readings.bow_scale_kg = 0.5 + 0.00377 * k;
    w.readings.target.density_kgm3 = 1020.0 + 0.1 * k;
    const FirstMissionReport r = slocumFirstMission(v, w);
    if (anyContains(r.warnings, "HEAVY")) continue;
    EXPECT_GE(r.predicted.net_buoyancy_kg, 0.0) << k;
    EXPECT_LT(r.predicted.net_buoyancy_kg, 0.001) << k;
  }
}

TEST(SlocumFirstMission, BadInputNamesTheField) {
  const VehicleProfile v = slocum();
  TankWeighing w = appendixB();
  w.vehicle = "hugin1000";
  EXPECT_EQ(errorField(v, w), "vehicle");

  w = appendixB();
  w.ballast.at(kRailPort) = 0.200;  // more than the 120 g rail
  EXPECT_EQ(errorField(v, w), "ballast_g.wing_rail_port");
  try {
    slocumFirstMission(v, w);
  } catch (const InputError& e) {
    EXPECT_NE(e.where().file.find("slocum_tank_weighing.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("200 g is more than the 120 g"), std::string::npos);
  }

  w = appendixB();
  (*w.bottles_after_tank_step_kg)[kAftUpper] = 0.500;
  EXPECT_EQ(errorField(v, w), "after_tank_step_g.aft_upper");

  w = appendixB();
  w.ballast.battery_angle_rad = 0.5;
  EXPECT_EQ(errorField(v, w), "roll_battery.angle_rad");

  w = appendixB();
  w.roll_test->applied[1].starboard = true;  // reading then turns the wrong way
  EXPECT_EQ(errorField(v, w), "roll_test.applied[1].roll_rad");

  const VehicleProfile hugin = loadVehicleProfile(kRes + "/vehicles/hugin1000.json");
  w = appendixB();
  w.vehicle.clear();
  EXPECT_EQ(errorField(hugin, w), "slocum");
}

}  // namespace auv
