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

}  // namespace
}  // namespace auv::sim
