#pragma once
// A mission plan file (docs/formats/mission-plan.md): which vehicle, what
// water, how it is ballasted, and the legs it flies, turned into the
// simulator's Scenario and options. Every field is read through JsonReader,
// so a bad plan is reported with file and JSON path.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/depth_autopilot.h"
#include "sim/glider_simulator.h"
#include "sim/simulator.h"
#include "sim/vehicle_model.h"
#include "sim/water_column.h"
#include "vehicle/json_reader.h"
#include "vehicle/vehicle_profile.h"

namespace auv::sim {

struct MissionPlan {
  std::string file;
  std::string vehicle;       // profile id, e.g. "delphin2"
  std::string description;
  Scenario scenario;         // without the installed weights (see resolveScenario)
  SimOptions options;
  WaterColumn water = WaterColumn::uniform(1025.0);
  std::optional<bool> anti_windup;  // overrides the vehicle's autopilot if set
  std::vector<double> installed_kg;  // adjustment weight at each profile point; empty = none
  // A glider plan ("yo" legs): its legs and the same initial state, ballast
  // and error as `scenario` (whose legs are then empty).
  GliderScenario glider;
  bool isGliderPlan() const { return !glider.legs.empty(); }
};

MissionPlan parseMissionPlan(const nlohmann::json& doc, const std::string& file);
MissionPlan loadMissionPlan(const std::string& file);

// The plan's scenario with its installed weights placed at the profile's
// adjustment points (InputError("installed") if they do not match).
Scenario resolveScenario(const MissionPlan& plan, const VehicleProfile& profile);
GliderScenario resolveGliderScenario(const MissionPlan& plan, const VehicleProfile& profile);

// A water description: {"density_kgm3": ...} or {"cast": [...]} (the plan's
// "water" object), from a reader or from a JSON file that is either such an
// object or holds one under "water".
WaterColumn parseWater(const JsonReader& water);
WaterColumn loadWaterFile(const std::string& file);

// The simulator's view of a vehicle: its profile's own sim sections, or, for
// a profile without them, <resource_dir>/sim/<id>_hydrodynamics.json.
struct SimVehicle {
  VehicleModel model;
  DepthAutopilotConfig autopilot;
};
SimVehicle loadSimVehicle(const VehicleProfile& profile, const std::string& resource_dir);

}  // namespace auv::sim
