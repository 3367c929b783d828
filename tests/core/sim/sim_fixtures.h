#pragma once
// Shared set-up for the simulator tests: the Delphin2 profile as shipped.
#include <string>

#include "sim/model_loader.h"
#include "vehicle/profile_loader.h"

namespace auv::sim::testing {

inline std::string delphin2Path() { return std::string(AUV_RESOURCE_DIR) + "/vehicles/delphin2.json"; }

struct Delphin2 {
  VehicleProfile profile = loadVehicleProfile(delphin2Path());
  VehicleModel model = loadVehicleModel(profile);
  DepthAutopilotConfig autopilot = loadAutopilotConfig(profile);
};

}  // namespace auv::sim::testing
