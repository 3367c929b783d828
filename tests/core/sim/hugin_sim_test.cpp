// HUGIN 1000 with the geometry-scaled hydrodynamics of
// resources/sim/hugin1000_hydrodynamics.json: the tuning target (160 rpm ->
// 2 m/s) and the flight autopilot's depth changes in EOS-80 sea water.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/units.h"
#include "sim/model_loader.h"
#include "sim/simulator.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"

namespace auv::sim {
namespace {

struct Hugin {
  VehicleProfile profile = loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/hugin1000.json");
  std::string file = std::string(AUV_RESOURCE_DIR) + "/sim/hugin1000_hydrodynamics.json";
  nlohmann::json doc = JsonReader::parseFile(file);
  VehicleModel model = loadVehicleModel(profile, doc, file);
  DepthAutopilotConfig autopilot = loadAutopilotConfig(doc, file);
};

WaterColumn sea() {
  const std::vector<CtdPoint> cast = {{0, 8, 34.5}, {100, 5, 35.0}, {1000, 4, 35.0}};
  return WaterColumn::fromCast(cast, 1000.0);
}

TEST(HuginSim, GeometryFromTheProfileAndNoThrusters) {
  const Hugin h;
  EXPECT_DOUBLE_EQ(h.model.body.mass_kg, 1498.0);
  EXPECT_NEAR(h.model.body.hull.volume_m3, (1498.0 + 65.0) / 1024.8, 1e-12);
  EXPECT_NEAR(h.model.body.r_g_m.z(), 0.020, 1e-12);  // bg_mm, CG under CB
  EXPECT_EQ(h.model.thruster_count, 0);
}

TEST(HuginSim, OneHundredSixtyRpmGivesTwoMetresPerSecond) {
  const Hugin h;
  Scenario sc;
  sc.net_buoyancy_n = 0.0;
  sc.initial_depth_m = 50.0;
  sc.legs = {{400.0, 50.0, 160.0}};
  const SimTrace tr = simulate(h.model, h.autopilot, sea(), sc);
  EXPECT_NEAR(tr.speed_mps.back(), 2.0, 0.05);
  EXPECT_NEAR(tr.prop_rpm.back(), 160.0, 1e-9);
  EXPECT_NEAR(tr.depth_m.back(), 50.0, 0.05);
}

TEST(HuginSim, FlightAutopilotChangesDepthWithoutOvershootingFar) {
  const Hugin h;
  Scenario sc;
  sc.net_buoyancy_n = 5.0;
  sc.initial_depth_m = 20.0;
  sc.initial_speed_mps = 2.0;
  sc.legs = {{200.0, 20.0, 160.0}, {400.0, 50.0, 160.0}};
  const SimTrace tr = simulate(h.model, h.autopilot, sea(), sc);
  double deepest = 0.0, steepest = 0.0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    deepest = std::max(deepest, tr.depth_m[i]);
    steepest = std::min(steepest, tr.pitch_rad[i]);
  }
  EXPECT_LT(deepest, 50.5);
  EXPECT_NEAR(tr.depth_m.back(), 50.0, 0.05);
  // Dives at the pitch-bias limit (15 deg) with a transient beyond it.
  EXPECT_LT(units::radToDeg(steepest), -14.0);
  EXPECT_GT(units::radToDeg(steepest), -25.0);
  // Sea water gets denser with depth: the incompressible hull gains buoyancy.
  EXPECT_GT(tr.net_buoyancy_n.back(), tr.net_buoyancy_n.front() + 3.0);
}

// Mean of the logged elevator over [t0, t1) of a trace.
double elevatorMeanDeg(const SimTrace& tr, double t0, double t1) {
  double s = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < tr.size(); ++i)
    if (tr.time_s[i] >= t0 && tr.time_s[i] < t1) s += tr.elevator_rad[i], ++n;
  return units::radToDeg(s / n);
}

// A 30 m descent at 0.25 m/s between two level legs at 160 rpm, the depth
// command ramped by one leg, or (staircase) by 1-s legs.
Scenario descent(bool staircase) {
  Scenario sc;
  sc.net_buoyancy_n = 20.0;
  sc.initial_depth_m = 50.0;
  sc.initial_speed_mps = 2.0;
  sc.legs = {{200.0, 50.0, 160.0}};
  if (staircase) {
    for (int k = 1; k <= 120; ++k) sc.legs.push_back({1.0, 50.0 + 0.25 * k, 160.0});
  } else {
    DepthLeg ramp{120.0, 80.0, 160.0};
    ramp.ramp = true;
    sc.legs.push_back(ramp);
  }
  sc.legs.push_back({200.0, 80.0, 160.0});
  return sc;
}

TEST(HuginSim, RampLegMovesTheDepthCommandInAStraightLineAndTheVehicleFollows) {
  const Hugin h;
  SimOptions o;
  o.trace_interval_s = 1.0;
  const SimTrace tr = simulate(h.model, h.autopilot, sea(), descent(false), o);
  auto at = [&](double t) { return static_cast<std::size_t>(std::lround(t)); };
  EXPECT_DOUBLE_EQ(tr.depth_cmd_m[at(199)], 50.0);
  EXPECT_NEAR(tr.depth_cmd_m[at(230)], 57.5, 1e-9);  // a quarter of the way
  EXPECT_NEAR(tr.depth_cmd_m[at(290)], 72.5, 1e-9);
  EXPECT_DOUBLE_EQ(tr.depth_cmd_m[at(330)], 80.0);
  // Settled on the ramp: the vehicle descends at the command's rate.
  EXPECT_NEAR((tr.depth_m[at(310)] - tr.depth_m[at(270)]) / 40.0, 0.25, 0.005);
}

TEST(HuginSim, RampedDescentLoggedAtOneHertzKeepsTheElevatorMeanAStaircaseDoesNot) {
  // The mean of the 1 Hz log over the settled descent against the 20 Hz
  // mean of the same flight (the elevator the vehicle really held).
  const Hugin h;
  SimOptions fast, slow;
  fast.trace_interval_s = 0.05;
  slow.trace_interval_s = 1.0;
  for (bool staircase : {false, true}) {
    const double e_fast = elevatorMeanDeg(simulate(h.model, h.autopilot, sea(), descent(staircase), fast), 260, 320);
    const double e_slow = elevatorMeanDeg(simulate(h.model, h.autopilot, sea(), descent(staircase), slow), 260, 320);
    if (staircase)  // each 1 Hz sample lands on a command step: one phase of the kick
      EXPECT_GT(std::abs(e_slow - e_fast), 0.1) << e_slow << " vs " << e_fast;
    else
      EXPECT_NEAR(e_slow, e_fast, 0.02);
  }
}

}  // namespace
}  // namespace auv::sim
