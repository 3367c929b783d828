#include "sim/mission_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"

namespace auv::sim {
namespace {

const std::string kRes = AUV_RESOURCE_DIR;

TEST(MissionPlan, Delphin2HoverPlanReproducesFigure14b) {
  const MissionPlan plan = loadMissionPlan(kRes + "/examples/delphin2_hover.plan.json");
  EXPECT_EQ(plan.vehicle, "delphin2");
  ASSERT_EQ(plan.scenario.legs.size(), 3u);
  EXPECT_DOUBLE_EQ(plan.scenario.legs[1].depth_m, 2.0);
  EXPECT_DOUBLE_EQ(plan.scenario.legs[1].prop_demand, 0.0);
  EXPECT_DOUBLE_EQ(*plan.scenario.net_buoyancy_n, 6.0);
  ASSERT_TRUE(plan.anti_windup.has_value());
  const SimVehicle v = loadSimVehicle(loadVehicleProfile(kRes + "/vehicles/" + plan.vehicle + ".json"), kRes);
  DepthAutopilotConfig ap = v.autopilot;
  ap.anti_windup = *plan.anti_windup;
  const SimTrace tr = simulate(v.model, ap, plan.water, plan.scenario, plan.options);
  // 1 -> 2 m step: overshoot about 0.2 m (sec. 8.1), depth held at the end.
  double deepest = 0.0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    if (tr.time_s[i] >= 60 && tr.time_s[i] < 120) deepest = std::max(deepest, tr.depth_m[i]);
  }
  EXPECT_GT(deepest - 2.0, 0.1);
  EXPECT_LT(deepest - 2.0, 0.3);
  EXPECT_NEAR(tr.depth_m.back(), 1.0, 0.01);
}

TEST(MissionPlan, HuginSurveyPlanFliesItsLegsInTheCast) {
  const MissionPlan plan = loadMissionPlan(kRes + "/examples/hugin1000_survey.plan.json");
  const VehicleProfile profile = loadVehicleProfile(kRes + "/vehicles/hugin1000.json");
  const SimVehicle v = loadSimVehicle(profile, kRes);
  const SimTrace tr = simulate(v.model, v.autopilot, plan.water, resolveScenario(plan, profile), plan.options);
  EXPECT_NEAR(tr.time_s.back(), 6300.0, 1e-6);
  auto at = [&](double t) {
    const auto it = std::lower_bound(tr.time_s.begin(), tr.time_s.end(), t - 1e-9);
    return static_cast<std::size_t>(it - tr.time_s.begin());
  };
  EXPECT_NEAR(tr.depth_m[at(2100)], 50.0, 0.2);   // end of the 50 m leg (noise 2 cm)
  EXPECT_NEAR(tr.depth_m[at(3900)], 100.0, 0.2);  // end of the 100 m leg
  EXPECT_NEAR(tr.speed_mps[at(3900)], 2.0, 0.06);
  EXPECT_NEAR(tr.salinity_psu[at(3900)], 35.0, 0.015);  // water from the cast (+ 3 mPSU noise)
  EXPECT_NEAR(units::radToDeg(tr.heading_rad[at(3900)]), 180.0, 0.5);  // reciprocal survey line
  // Trimmed to +4.9 N at the start depth; sea water denser below: lighter.
  EXPECT_NEAR(tr.truth.net_buoyancy_start_n, 4.9, 1e-9);
  EXPECT_GT(tr.net_buoyancy_n[at(3900)], 4.9 + 5.0);
  // plan.scenario is complete for a plan without installed weights.
  EXPECT_EQ(resolveScenario(plan, profile).extra_masses.size(), plan.scenario.extra_masses.size());
}

TEST(MissionPlan, BallastErrorPlanCarriesItsKnownError) {
  const MissionPlan plan = loadMissionPlan(kRes + "/examples/hugin1000_ballast_error.plan.json");
  EXPECT_EQ(plan.installed_kg, (std::vector<double>{7.2, 7.2, 25.2, 25.2}));
  EXPECT_DOUBLE_EQ(plan.scenario.ballast_error.net_buoyancy_kg, 3.0);
  EXPECT_DOUBLE_EQ(plan.scenario.ballast_error.cg_shift_m.x(), 0.005);
  EXPECT_TRUE(std::isnan(plan.scenario.legs[0].heading_rad));
  EXPECT_DOUBLE_EQ(plan.scenario.legs[1].heading_rad, units::degToRad(180.0));
  VehicleProfile delphin = loadVehicleProfile(kRes + "/vehicles/delphin2.json");
  try {
    (void)resolveScenario(plan, delphin);  // 4 masses for 2 points
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "installed_kg");  // the plan's field, in the plan file
    EXPECT_EQ(e.where().file, plan.file);
  }
}

TEST(MissionPlan, ErrorsNameTheField) {
  const std::string text = R"({"format": "auvballast-mission-plan", "version": 1, "vehicle": "delphin2",
    "water": {"density_kgm3": 1000}, "legs": [{"type": "hover", "depth_m": 1, "duration_s": 10},
    {"type": "glide", "depth_m": 1, "duration_s": 10}]})";
  try {
    (void)parseMissionPlan(JsonReader::parseText(text, "t.plan.json"), "t.plan.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "legs[1].type");
    EXPECT_EQ(e.where().file, "t.plan.json");
  }
  const std::string no_water = R"({"format": "auvballast-mission-plan", "version": 1, "vehicle": "x",
    "water": {}, "legs": [{"type": "hover", "depth_m": 1, "duration_s": 10}]})";
  EXPECT_THROW((void)parseMissionPlan(JsonReader::parseText(no_water, "w.json"), "w.json"), InputError);
  const std::string bad_bool = R"({"format": "auvballast-mission-plan", "version": 1, "vehicle": "x",
    "water": {"density_kgm3": 1000}, "legs": [{"type": "hover", "depth_m": 1, "duration_s": 10}],
    "options": {"anti_windup": "yes"}})";
  try {
    (void)parseMissionPlan(JsonReader::parseText(bad_bool, "b.json"), "b.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "options.anti_windup");
  }
  const std::string ramp = R"({"format": "auvballast-mission-plan", "version": 1, "vehicle": "x",
    "water": {"density_kgm3": 1000}, "legs": [{"type": "depth", "depth_m": 5, "prop_demand": 20,
    "duration_s": 10, "ramp": true}, {"type": "hover", "depth_m": 1, "duration_s": 10, "ramp": 1}]})";
  const std::string ramp_ok = R"({"format": "auvballast-mission-plan", "version": 1, "vehicle": "x",
    "water": {"density_kgm3": 1000}, "legs": [{"type": "depth", "depth_m": 5, "prop_demand": 20,
    "duration_s": 10, "ramp": true}, {"type": "hover", "depth_m": 1, "duration_s": 10}]})";
  const MissionPlan with_ramp = parseMissionPlan(JsonReader::parseText(ramp_ok, "r.json"), "r.json");
  EXPECT_TRUE(with_ramp.scenario.legs[0].ramp);
  EXPECT_FALSE(with_ramp.scenario.legs[1].ramp);
  try {
    (void)parseMissionPlan(JsonReader::parseText(ramp, "r.json"), "r.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "legs[1].ramp");  // legs[0]'s true was read
  }
}

TEST(MissionPlan, VehicleWithoutSimParametersIsReported) {
  VehicleProfile p = loadVehicleProfile(kRes + "/vehicles/hugin1000.json");
  p.id = "nosuchvehicle";
  EXPECT_THROW((void)loadSimVehicle(p, kRes), InputError);
}

}  // namespace
}  // namespace auv::sim
