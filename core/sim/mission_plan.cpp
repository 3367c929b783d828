#include "sim/mission_plan.h"

#include <filesystem>
#include <limits>

#include "common/input_error.h"
#include "common/units.h"
#include "sim/model_loader.h"
#include "vehicle/json_reader.h"

namespace auv::sim {
namespace {

WaterColumn readWater(const JsonReader& w) {
  if (w.has("cast")) {
    std::vector<CtdPoint> cast;
    for (const JsonReader& level : w.array("cast")) {
      cast.push_back({level.numberIn("depth_m", 0.0, 11000.0), level.numberIn("temperature_degC", -2.0, 40.0),
                      level.numberIn("salinity_psu", 0.0, 42.0)});
    }
    const double max_depth = w.numberIn("max_depth_m", 1.0, 11000.0, 1000.0);
    return WaterColumn::fromCast(cast, max_depth, w.numberIn("grid_m", 0.01, 100.0, 1.0),
                                 w.numberIn("latitude_deg", -90.0, 90.0, 45.0));
  }
  if (!w.has("density_kgm3")) {
    w.fail("density_kgm3", "no water given", "give \"density_kgm3\" (uniform) or a \"cast\" of depth/T/S levels");
  }
  return WaterColumn::uniform(w.numberIn("density_kgm3", 950.0, 1050.0), w.numberIn("temperature_degC", -2.0, 40.0, 15.0),
                              w.numberIn("salinity_psu", 0.0, 42.0, 0.0));
}

DepthLeg readLeg(const JsonReader& l) {
  const std::string type = l.text("type");
  DepthLeg leg;
  leg.duration_s = l.numberIn("duration_s", 1e-3, 1e7);
  leg.depth_m = l.numberIn("depth_m", 0.0, 11000.0);
  leg.pitch_rad = units::degToRad(l.numberIn("pitch_deg", -45.0, 45.0, 0.0));
  if (type == "hover") {
    if (l.has("prop_demand")) l.fail("prop_demand", "a hover leg has no propeller demand", "use type \"depth\"");
    leg.prop_demand = 0.0;
  } else if (type == "depth") {
    leg.prop_demand = l.numberIn("prop_demand", 0.0, 1e4);
  } else {
    l.fail("type", "unknown leg type '" + type + "'", "use \"hover\" or \"depth\"");
  }
  return leg;
}

bool readBool(const JsonReader& r, const std::string& key) {
  const nlohmann::json& v = r.node().at(key);
  if (!v.is_boolean()) r.fail(key, "expected true or false", "write true or false without quotes");
  return v.get<bool>();
}

}  // namespace

MissionPlan parseMissionPlan(const nlohmann::json& doc, const std::string& file) {
  const JsonReader root(doc, file);
  const std::string format = root.text("format");
  if (format != "auvballast-mission-plan") {
    root.fail("format", "not a mission plan", "set \"format\": \"auvballast-mission-plan\"");
  }
  if (root.numberIn("version", 1.0, 1.0) != 1.0) root.fail("version", "unsupported", "use version 1");
  MissionPlan plan;
  plan.file = file;
  plan.vehicle = root.text("vehicle");
  plan.description = root.text("description", "");
  plan.water = readWater(root.child("water"));

  Scenario& sc = plan.scenario;
  if (auto init = root.optionalChild("initial")) {
    sc.initial_depth_m = init->numberIn("depth_m", -1.0, 11000.0, 0.0);
    sc.initial_speed_mps = init->numberIn("speed_mps", 0.0, 20.0, 0.0);
    sc.initial_pitch_rad = units::degToRad(init->numberIn("pitch_deg", -90.0, 90.0, 0.0));
    if (init->has("net_buoyancy_n")) sc.net_buoyancy_n = init->numberIn("net_buoyancy_n", -1e5, 1e5);
  }
  for (const JsonReader& l : root.array("legs")) sc.legs.push_back(readLeg(l));
  if (sc.legs.empty()) root.fail("legs", "no legs", "add at least one hover or depth leg");
  if (root.has("events")) {
    const double end = scenarioDuration(sc);
    for (const JsonReader& e : root.array("events")) {
      const double t = e.numberIn("time_s", 0.0, end);
      sc.buoyancy_changes.push_back({t, e.numberIn("buoyancy_change_n", -1e5, 1e5)});
    }
  }
  if (root.has("ballast_changes")) {
    for (const JsonReader& m : root.array("ballast_changes")) {
      sc.extra_masses.push_back({m.numberIn("mass_kg", -1e4, 1e4),
                                 {units::mmToM(m.numberIn("x_mm", -1e5, 1e5)), units::mmToM(m.numberIn("y_mm", -1e5, 1e5)),
                                  units::mmToM(m.numberIn("z_mm", -1e5, 1e5))}});
    }
  }

  SimOptions& o = plan.options;
  if (auto opt = root.optionalChild("options")) {
    o.dt_s = opt->numberIn("dt_s", 1e-4, 1.0, o.dt_s);
    o.trace_interval_s = opt->numberIn("trace_interval_s", 1e-4, 3600.0, o.trace_interval_s);
    o.seed = static_cast<std::uint64_t>(opt->numberIn("seed", 0.0, 9007199254740991.0, 1.0));
    if (opt->has("surface_model")) o.surface_model = readBool(*opt, "surface_model");
    if (opt->has("preload_hover_integrator")) o.preload_hover_integrator = readBool(*opt, "preload_hover_integrator");
    if (opt->has("anti_windup")) plan.anti_windup = readBool(*opt, "anti_windup");
    if (auto n = opt->optionalChild("noise")) {
      o.noise.depth_m = n->numberIn("depth_m", 0.0, 100.0, 0.0);
      o.noise.depth_rate_mps = n->numberIn("depth_rate_mps", 0.0, 10.0, 0.0);
      o.noise.pitch_rad = units::degToRad(n->numberIn("pitch_deg", 0.0, 45.0, 0.0));
      o.noise.pitch_rate_radps = units::degToRad(n->numberIn("pitch_rate_degps", 0.0, 90.0, 0.0));
      o.noise.roll_rad = units::degToRad(n->numberIn("roll_deg", 0.0, 45.0, 0.0));
      o.noise.speed_mps = n->numberIn("speed_mps", 0.0, 10.0, 0.0);
    }
  }
  return plan;
}

MissionPlan loadMissionPlan(const std::string& file) { return parseMissionPlan(JsonReader::parseFile(file), file); }

SimVehicle loadSimVehicle(const VehicleProfile& profile, const std::string& resource_dir) {
  if (profile.sections.contains("hydrodynamics")) {
    return {loadVehicleModel(profile), loadAutopilotConfig(profile)};
  }
  const std::string file = resource_dir + "/sim/" + profile.id + "_hydrodynamics.json";
  if (!std::filesystem::exists(file)) {
    throw InputError("hydrodynamics", "vehicle '" + profile.id + "' has no simulation parameters",
                     "add \"hydrodynamics\", \"actuators\", \"sim_assumptions\" and \"autopilot\" to " + profile.file +
                         " or provide " + file,
                     {profile.file, 0, 0});
  }
  const nlohmann::json doc = JsonReader::parseFile(file);
  return {loadVehicleModel(profile, doc, file), loadAutopilotConfig(doc, file)};
}

}  // namespace auv::sim
