#pragma once
// Shared set-up for the simulator tests: the Delphin2 profile as shipped and
// HUGIN 1000 with its geometry-scaled hydrodynamics.
#include <string>

#include "sim/mission_plan.h"
#include "sim/model_loader.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"

namespace auv::sim::testing {

inline std::string resourceDir() { return std::string(AUV_RESOURCE_DIR); }
inline std::string delphin2Path() { return resourceDir() + "/vehicles/delphin2.json"; }

struct Delphin2 {
  VehicleProfile profile = loadVehicleProfile(delphin2Path());
  VehicleModel model = loadVehicleModel(profile);
  DepthAutopilotConfig autopilot = loadAutopilotConfig(profile);
};

struct HuginSim {
  VehicleProfile profile = loadVehicleProfile(resourceDir() + "/vehicles/hugin1000.json");
  SimVehicle sim = loadSimVehicle(profile, resourceDir());
  const VehicleModel& model() const { return sim.model; }
  const DepthAutopilotConfig& autopilot() const { return sim.autopilot; }
};

// The survey plan's water: a Norwegian-coast CTD cast.
inline WaterColumn huginSea() {
  const std::vector<CtdPoint> cast = {{0, 9.0, 33.5}, {20, 8.0, 34.5}, {100, 7.0, 35.0}, {300, 6.5, 35.1}};
  return WaterColumn::fromCast(cast, 300.0, 1.0, 60.0);
}

// The survey plan's kit pieces: about 1 kg light and level at the surface.
inline std::vector<double> huginInstalledKg() { return {7.2, 7.2, 25.7, 25.7}; }

}  // namespace auv::sim::testing
