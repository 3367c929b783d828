#pragma once
// Reads the simulator's view of a vehicle from its profile: the generic part
// (mass, hull, CB, CG) plus the "hydrodynamics", "actuators",
// "sim_assumptions" and "autopilot" sections. Every number is read through
// JsonReader, so a missing or out-of-range field is reported with its file and
// JSON path. A vehicle whose profile has no such sections (HUGIN) can take
// them from a separate file instead.
#include <string>

#include <nlohmann/json.hpp>

#include "sim/depth_autopilot.h"
#include "sim/vehicle_model.h"
#include "vehicle/vehicle_profile.h"

namespace auv::sim {

// Sections from the profile itself.
VehicleModel loadVehicleModel(const VehicleProfile& profile);
DepthAutopilotConfig loadAutopilotConfig(const VehicleProfile& profile);

// Sections from `sections_doc` (a JSON object holding them), read from `file`.
VehicleModel loadVehicleModel(const VehicleProfile& profile, const nlohmann::json& sections_doc,
                              const std::string& file);
DepthAutopilotConfig loadAutopilotConfig(const nlohmann::json& sections_doc, const std::string& file);

}  // namespace auv::sim
