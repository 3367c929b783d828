// What the vehicle does with the pieces actually installed, and the plan's
// starting points shared by the CLI and the GUI. Oracles: the plan's own
// prediction when the technician installs exactly the plan (an independent
// code path through the ballast solver's evaluation), conservation of mass
// (each extra kg is one kg less net buoyancy at every planned point), the
// small-angle pitch sensitivity m g dx / (W BG) and EOS-80 computed here.
#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "plan_fixture.h"
#include "planning/installed_prediction.h"
#include "planning/plan_sources.h"

using namespace auv;
using namespace auv::planning_test;

namespace {

PreMissionInput baseInput() {
  PreMissionInput in;
  in.installed_kg = {10.8, 10.8, 22.8, 22.8};  // thesis App. G.2
  in.estimate = estimateAt(5.3, 12.0, 1.5, 8.0, 35.0, 100.0);
  in.next = nextMissionWater(water(6.0, 35.0, 50.0), 120.0, "operator");
  return in;
}

}  // namespace

TEST(InstalledPrediction, InstallingThePlanReproducesThePlansPrediction) {
  const VehicleProfile v = hugin();
  const PreMissionInput in = baseInput();
  const PreMissionPlan p = planPreMission(v, in);
  const std::vector<double> after = installedAfterPlan(in.installed_kg, p);
  ASSERT_EQ(after.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(after[i], in.installed_kg[i] + p.points[i].add_kg, 1e-9);
  const InstalledPrediction r = predictInstalled(v, p, in.installed_kg, after);
  EXPECT_NEAR(r.net_buoyancy_kg, p.predicted.net_buoyancy_kg, 1e-9);
  EXPECT_NEAR(r.pitch_deg, p.predicted.pitch_deg, 1e-9);
  EXPECT_NEAR(r.roll_deg, p.predicted.roll_deg, 1e-9);
  EXPECT_NEAR(r.net_sigma_kg, p.net_sigma_kg, 1e-12);
  EXPECT_NEAR(r.pitch_sigma_deg, p.pitch_sigma_deg, 1e-9);
  EXPECT_NEAR(r.roll_sigma_deg, p.roll_sigma_deg, 1e-9);
  ASSERT_EQ(r.net_at_points_kg.size(), p.at_points.size());
  for (std::size_t i = 0; i < p.at_points.size(); ++i) EXPECT_NEAR(r.net_at_points_kg[i], p.at_points[i].net_after_kg, 1e-9);
  EXPECT_EQ(r.buoyancy_in_band, p.buoyancy_in_band);
  EXPECT_EQ(r.pitch_in_band, p.pitch_in_band);
  EXPECT_EQ(r.safe, p.safe);
}

TEST(InstalledPrediction, FlyingPitchFollowsThePlanAndMovesLessThanAtRest) {
  // With a cruise speed the plan predicts the pitch flown level there;
  // installing exactly the plan gives the same, and moving one 1.2 kg piece
  // fore -> aft moves the flying pitch far less than the pitch at rest.
  const VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  in.estimate.cruise_speed_mps = 2.0;
  const PreMissionPlan p = planPreMission(v, in);
  ASSERT_TRUE(p.flight_pitch_after_deg.has_value());
  ASSERT_TRUE(p.flight_pitch_before_deg.has_value());
  EXPECT_DOUBLE_EQ(p.flight_speed_mps, 2.0);
  std::vector<double> after = installedAfterPlan(in.installed_kg, p);
  const InstalledPrediction r = predictInstalled(v, p, in.installed_kg, after);
  ASSERT_TRUE(r.flight_pitch_deg.has_value());
  EXPECT_NEAR(*r.flight_pitch_deg, *p.flight_pitch_after_deg, 1e-9);
  EXPECT_EQ(*r.flight_pitch_in_band, *p.flight_pitch_in_band);
  after[0] -= 1.2;  // fore / starboard -> aft / starboard
  after[2] += 1.2;
  const InstalledPrediction moved = predictInstalled(v, p, in.installed_kg, after);
  const double at_rest = moved.pitch_deg - r.pitch_deg, in_flight = *moved.flight_pitch_deg - *r.flight_pitch_deg;
  EXPECT_GT(at_rest, 0.5);  // nose up at rest: several degrees
  // In flight the planes take the moment; their changed lift shifts the
  // heave balance, so on a light vehicle the nose even drops a little (the
  // simulator agrees: tests/core/analysis/level_flight_test.cpp).
  EXPECT_LT(std::abs(in_flight), 0.1 * at_rest);
  EXPECT_GT(std::abs(in_flight), 1e-3);
  // Without a cruise speed nothing is claimed.
  EXPECT_FALSE(planPreMission(v, baseInput()).flight_pitch_after_deg.has_value());
}

TEST(InstalledPrediction, OneExtraPieceCostsItsMassAtEveryPlannedPoint) {
  const VehicleProfile v = hugin();
  const PreMissionInput in = baseInput();
  const PreMissionPlan p = planPreMission(v, in);
  std::vector<double> after = installedAfterPlan(in.installed_kg, p);
  const InstalledPrediction planned = predictInstalled(v, p, in.installed_kg, after);
  after[2] += 1.2;  // one 1.2 kg piece too many at aft / starboard
  const InstalledPrediction r = predictInstalled(v, p, in.installed_kg, after);
  ASSERT_EQ(r.net_at_points_kg.size(), 3u);  // operating, surface, deepest
  for (std::size_t i = 0; i < r.net_at_points_kg.size(); ++i) {
    EXPECT_NEAR(planned.net_at_points_kg[i] - r.net_at_points_kg[i], 1.2, 1e-9);
  }
  EXPECT_NEAR(r.add_kg[2] - planned.add_kg[2], 1.2, 1e-12);
  EXPECT_GT(r.pitch_deg, planned.pitch_deg);  // aft mass: nose up
  EXPECT_GT(r.roll_deg, planned.roll_deg);    // starboard mass: starboard down
}

TEST(InstalledPrediction, APieceMovedAftPitchesByTheSmallAngleLaw) {
  const VehicleProfile v = hugin();
  const PreMissionInput in = baseInput();
  const PreMissionPlan p = planPreMission(v, in);
  std::vector<double> after = installedAfterPlan(in.installed_kg, p);
  ASSERT_GE(after[0], 1.2);
  const InstalledPrediction planned = predictInstalled(v, p, in.installed_kg, after);
  after[0] -= 1.2;  // fore / starboard -> aft / starboard: same mass, same buoyancy
  after[2] += 1.2;
  const InstalledPrediction r = predictInstalled(v, p, in.installed_kg, after);
  EXPECT_NEAR(r.net_buoyancy_kg, planned.net_buoyancy_kg, 1e-9);
  // Small angles: d(pitch) = m dx / (W BG), nose up for mass moved aft; W
  // the vehicle's mass, BG = z_G - z_B of the estimated vehicle.
  double W = p.vehicle.mass.mass_kg;
  for (const auto& pt : p.points) W += pt.add_kg;
  const double bg = p.vehicle.mass.cg_m.z() - v.cb_m.z();
  const double dx = v.points[0].position_m.x() - v.points[2].position_m.x();
  const double expected_deg = units::radToDeg(1.2 * dx / (W * bg));
  EXPECT_NEAR(r.pitch_deg - planned.pitch_deg, expected_deg, 0.03 * expected_deg);
  EXPECT_GT(expected_deg, 1.0);
  // Along one side: roll unchanged to small-angle accuracy.
  EXPECT_NEAR(r.roll_deg, planned.roll_deg, 0.02);
}

TEST(InstalledPrediction, RefusesNegativeOrOverCapacityMasses) {
  const VehicleProfile v = hugin();
  const PreMissionInput in = baseInput();
  const PreMissionPlan p = planPreMission(v, in);
  std::vector<double> after = installedAfterPlan(in.installed_kg, p);
  after[1] = -1.2;
  try {
    predictInstalled(v, p, in.installed_kg, after);
    FAIL() << "negative mass accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fore_port"), std::string::npos) << e.what();
  }
  after[1] = v.points[1].capacity_kg + 1.2;
  EXPECT_THROW(predictInstalled(v, p, in.installed_kg, after), InputError);
  EXPECT_THROW(predictInstalled(v, p, in.installed_kg, {1.0, 2.0}), InputError);
}

TEST(PlanSources, PhysicalReportGivesItsEstimateAndTheClassicBalance) {
  const VehicleProfile v = hugin();
  const nlohmann::json report = {
      {"net_buoyancy_kg", 2.5},
      {"net_buoyancy_sigma_kg", 0.2},
      {"cg_offset_mm", {{"x", 3.0}, {"y", -0.5}}},
      {"cg_offset_sigma_mm", {{"x", 0.1}, {"y", 0.05}}},
      {"errors", {{"depth_m", 0.2}, {"pitch_deg", -0.3}, {"roll_deg", 0.05}}},
      {"water", {{"temperature_degC", 7.0}, {"salinity_psu", 34.8}, {"depth_m", 50.0}}}};
  const PlanStart s = planStartFromReport(v, report, "fixture", PlanPolicy::Classic, 1570.0, std::nullopt);
  EXPECT_TRUE(s.physical);
  EXPECT_DOUBLE_EQ(s.estimate.net_buoyancy_kg, 2.5);
  // Oracle: rho(S, T, p) V(T, p) - recorded weight, EOS-80 and the profile hull.
  const double pr = seawater::pressureFromDepth(50.0);
  const double rho = seawater::density(34.8, 7.0, pr);
  EXPECT_NEAR(s.estimate.water.density_kgm3, rho, 1e-6);
  EXPECT_NEAR(s.classic_computed_imbalance_kg, rho * v.hull.volumeAt(7.0, s.estimate.water.pressure_dbar) - 1570.0, 1e-6);
  const PlannedWater w = lastMissionWater(s.estimate, 60.0);
  EXPECT_DOUBLE_EQ(w.temperature_degC, 7.0);
  EXPECT_DOUBLE_EQ(w.salinity_psu, 34.8);
  EXPECT_DOUBLE_EQ(w.depth_m, 50.0);
  EXPECT_DOUBLE_EQ(w.latitude_deg, 60.0);
}

TEST(PlanSources, DeviationsOnlyNeedTheClassicPolicyTheWeightAndTheWater) {
  const VehicleProfile v = hugin();
  // A thesis ballasting-file record: deviations, no estimate.
  const nlohmann::json report = {{"depth_deviation_m", 0.3}, {"pitch_deviation_deg", 1.1}, {"roll_deviation_deg", -0.2}};
  try {
    planStartFromReport(v, report, "row 2", PlanPolicy::Exact, 1570.0, MeasuredWater{6.5, 34.5});
    FAIL() << "exact policy without net buoyancy";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("net_buoyancy_kg"), std::string::npos);
  }
  EXPECT_THROW(planStartFromReport(v, report, "row 2", PlanPolicy::Classic, std::nullopt, MeasuredWater{6.5, 34.5}),
               InputError);
  EXPECT_THROW(planStartFromReport(v, report, "row 2", PlanPolicy::Classic, 1570.0, std::nullopt), InputError);
  const PlanStart s = planStartFromReport(v, report, "row 2", PlanPolicy::Classic, 1570.0, MeasuredWater{6.5, 34.5});
  EXPECT_FALSE(s.physical);
  ASSERT_TRUE(s.estimate.depth_error_m && s.estimate.pitch_error_deg && s.estimate.roll_deg);
  EXPECT_DOUBLE_EQ(*s.estimate.depth_error_m, 0.3);
  EXPECT_DOUBLE_EQ(*s.estimate.pitch_error_deg, 1.1);
  EXPECT_DOUBLE_EQ(*s.estimate.roll_deg, -0.2);
  // Surface balance of the thesis (eq. 5.2): rho(S, T, 0) V(T, 0) - weight.
  const double b = seawater::density(34.5, 6.5, 0.0) * v.hull.volumeAt(6.5, 0.0);
  EXPECT_NEAR(s.classic_computed_imbalance_kg, b - 1570.0, 1e-9);
  EXPECT_NEAR(s.estimate.net_buoyancy_kg, b - 1570.0, 1e-9);
}
