#include "sim/mission_plan.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "common/input_error.h"
#include "common/units.h"
#include "sim/model_loader.h"
#include "vehicle/installed_check.h"
#include "vehicle/json_reader.h"

namespace auv::sim {
namespace {
constexpr std::string_view kPlanDoc = "docs/formats/mission-plan.md";
}

WaterColumn parseWater(const JsonReader& w) {
  w.refuseUnknownKeys({"density_kgm3", "temperature_degC", "salinity_psu", "cast", "max_depth_m", "grid_m", "latitude_deg"},
                      kPlanDoc);
  if (w.has("cast")) {
    std::vector<CtdPoint> cast;
    for (const JsonReader& level : w.array("cast")) {
      level.refuseUnknownKeys({"depth_m", "temperature_degC", "salinity_psu"}, kPlanDoc);
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

WaterColumn loadWaterFile(const std::string& file) {
  const nlohmann::json doc = JsonReader::parseFile(file);
  const JsonReader root(doc, file);
  if (root.has("water")) {
    root.refuseUnknownKeys({"water", "description", "comment"}, kPlanDoc);
    return parseWater(root.child("water"));
  }
  return parseWater(root);
}

namespace {

bool readBool(const JsonReader& r, const std::string& key) {
  const nlohmann::json& v = r.node().at(key);
  if (!v.is_boolean()) r.fail(key, "expected true or false", "write true or false without quotes");
  return v.get<bool>();
}

DepthLeg readLeg(const JsonReader& l) {
  const std::string type = l.text("type");
  l.refuseUnknownKeys({"type", "duration_s", "depth_m", "pitch_deg", "heading_deg", "prop_demand", "ramp"}, kPlanDoc);
  DepthLeg leg;
  leg.duration_s = l.numberIn("duration_s", 1e-3, 1e7);
  leg.depth_m = l.numberIn("depth_m", 0.0, 11000.0);
  leg.pitch_rad = units::degToRad(l.numberIn("pitch_deg", -45.0, 45.0, 0.0));
  if (l.has("heading_deg")) leg.heading_rad = units::degToRad(l.numberIn("heading_deg", 0.0, 360.0));
  if (l.has("ramp")) leg.ramp = readBool(l, "ramp");
  if (type == "hover") {
    if (l.has("prop_demand")) l.fail("prop_demand", "a hover leg has no propeller demand", "use type \"depth\"");
    leg.prop_demand = 0.0;
  } else if (type == "depth") {
    leg.prop_demand = l.numberIn("prop_demand", 0.0, 1e4);
  } else {
    l.fail("type", "unknown leg type '" + type + "'", "use \"hover\", \"depth\" or (gliders) \"yo\"");
  }
  return leg;
}

YoLeg readYoLeg(const JsonReader& l) {
  l.refuseUnknownKeys({"type", "duration_s", "dive_to_m", "climb_to_m", "pump_cm3", "dive_pitch_deg", "climb_pitch_deg"},
                      kPlanDoc);
  YoLeg leg;
  leg.duration_s = l.numberIn("duration_s", 1e-3, 1e7);
  leg.dive_to_m = l.numberIn("dive_to_m", 0.0, 11000.0);
  leg.climb_to_m = l.numberIn("climb_to_m", 0.0, 11000.0);
  if (!(leg.dive_to_m > leg.climb_to_m)) l.fail("dive_to_m", "must be deeper than climb_to_m", "e.g. 100 and 10");
  if (l.has("pump_cm3")) leg.pump_m3 = l.numberIn("pump_cm3", 1.0, 1e5) * 1e-6;
  if (l.has("dive_pitch_deg")) leg.dive_pitch_rad = units::degToRad(l.numberIn("dive_pitch_deg", -80.0, -1.0));
  if (l.has("climb_pitch_deg")) leg.climb_pitch_rad = units::degToRad(l.numberIn("climb_pitch_deg", 1.0, 80.0));
  return leg;
}

}  // namespace

MissionPlan parseMissionPlan(const nlohmann::json& doc, const std::string& file) {
  const JsonReader root(doc, file);
  root.refuseUnknownKeys({"format", "version", "vehicle", "description", "water", "initial", "installed_kg", "ballast_error",
                          "legs", "events", "ballast_changes", "options"},
                         kPlanDoc);
  const std::string format = root.text("format");
  if (format != "auvballast-mission-plan") {
    root.fail("format", "not a mission plan", "set \"format\": \"auvballast-mission-plan\"");
  }
  if (root.numberIn("version", 1.0, 1.0) != 1.0) root.fail("version", "unsupported", "use version 1");
  MissionPlan plan;
  plan.file = file;
  plan.vehicle = root.text("vehicle");
  plan.description = root.text("description", "");
  plan.water = parseWater(root.child("water"));

  Scenario& sc = plan.scenario;
  if (auto init = root.optionalChild("initial")) {
    init->refuseUnknownKeys({"depth_m", "speed_mps", "pitch_deg", "heading_deg", "net_buoyancy_n"}, kPlanDoc);
    sc.initial_depth_m = init->numberIn("depth_m", -1.0, 11000.0, 0.0);
    sc.initial_speed_mps = init->numberIn("speed_mps", 0.0, 20.0, 0.0);
    sc.initial_pitch_rad = units::degToRad(init->numberIn("pitch_deg", -90.0, 90.0, 0.0));
    sc.initial_heading_rad = units::degToRad(init->numberIn("heading_deg", 0.0, 360.0, 0.0));
    if (init->has("net_buoyancy_n")) sc.net_buoyancy_n = init->numberIn("net_buoyancy_n", -1e5, 1e5);
  }
  if (root.has("installed_kg")) plan.installed_kg = root.numbers("installed_kg");
  if (auto e = root.optionalChild("ballast_error")) {
    e->refuseUnknownKeys({"net_buoyancy_kg", "cg_x_mm", "cg_y_mm", "cg_z_mm"}, kPlanDoc);
    sc.ballast_error.net_buoyancy_kg = e->numberIn("net_buoyancy_kg", -1e4, 1e4, 0.0);
    sc.ballast_error.cg_shift_m = {units::mmToM(e->numberIn("cg_x_mm", -1e4, 1e4, 0.0)),
                                   units::mmToM(e->numberIn("cg_y_mm", -1e4, 1e4, 0.0)),
                                   units::mmToM(e->numberIn("cg_z_mm", -1e4, 1e4, 0.0))};
  }
  GliderScenario& gl = plan.glider;
  for (const JsonReader& l : root.array("legs")) {
    const bool yo = l.text("type") == "yo";
    if ((yo && !sc.legs.empty()) || (!yo && !gl.legs.empty())) {
      l.fail("type", "a plan flies either yo legs (gliders) or hover/depth legs, not both", "split the plan");
    }
    if (yo) {
      gl.legs.push_back(readYoLeg(l));
    } else {
      sc.legs.push_back(readLeg(l));
    }
  }
  if (sc.legs.empty() && gl.legs.empty()) root.fail("legs", "no legs", "add at least one hover, depth or yo leg");
  if (!gl.legs.empty() && root.has("events")) {
    root.fail("events", "buoyancy events are not simulated for gliders", "remove \"events\" from a yo plan");
  }
  if (root.has("events")) {
    const double end = scenarioDuration(sc);
    for (const JsonReader& e : root.array("events")) {
      e.refuseUnknownKeys({"time_s", "buoyancy_change_n"}, kPlanDoc);
      const double t = e.numberIn("time_s", 0.0, end);
      sc.buoyancy_changes.push_back({t, e.numberIn("buoyancy_change_n", -1e5, 1e5)});
    }
  }
  if (root.has("ballast_changes")) {
    for (const JsonReader& m : root.array("ballast_changes")) {
      m.refuseUnknownKeys({"mass_kg", "x_mm", "y_mm", "z_mm"}, kPlanDoc);
      sc.extra_masses.push_back({m.numberIn("mass_kg", -1e4, 1e4),
                                 {units::mmToM(m.numberIn("x_mm", -1e5, 1e5)), units::mmToM(m.numberIn("y_mm", -1e5, 1e5)),
                                  units::mmToM(m.numberIn("z_mm", -1e5, 1e5))}});
    }
  }

  gl.extra_masses = sc.extra_masses;
  gl.net_buoyancy_n = sc.net_buoyancy_n;
  gl.ballast_error = sc.ballast_error;
  gl.initial_depth_m = std::max(0.0, sc.initial_depth_m);
  gl.initial_heading_rad = sc.initial_heading_rad;

  SimOptions& o = plan.options;
  if (auto opt = root.optionalChild("options")) {
    opt->refuseUnknownKeys({"dt_s", "trace_interval_s", "seed", "surface_model", "preload_hover_integrator", "anti_windup",
                            "noise"},
                           kPlanDoc);
    o.dt_s = opt->numberIn("dt_s", 1e-4, 1.0, o.dt_s);
    o.trace_interval_s = opt->numberIn("trace_interval_s", 1e-4, 3600.0, o.trace_interval_s);
    o.seed = static_cast<std::uint64_t>(opt->numberIn("seed", 0.0, 9007199254740991.0, 1.0));
    if (opt->has("surface_model")) o.surface_model = readBool(*opt, "surface_model");
    if (opt->has("preload_hover_integrator")) o.preload_hover_integrator = readBool(*opt, "preload_hover_integrator");
    if (opt->has("anti_windup")) plan.anti_windup = readBool(*opt, "anti_windup");
    if (auto n = opt->optionalChild("noise")) {
      n->refuseUnknownKeys({"depth_m", "depth_rate_mps", "pitch_deg", "pitch_rate_degps", "roll_deg", "speed_mps",
                            "heading_deg", "temperature_degC", "salinity_psu", "pressure_dbar"},
                           kPlanDoc);
      o.noise.depth_m = n->numberIn("depth_m", 0.0, 100.0, 0.0);
      o.noise.depth_rate_mps = n->numberIn("depth_rate_mps", 0.0, 10.0, 0.0);
      o.noise.pitch_rad = units::degToRad(n->numberIn("pitch_deg", 0.0, 45.0, 0.0));
      o.noise.pitch_rate_radps = units::degToRad(n->numberIn("pitch_rate_degps", 0.0, 90.0, 0.0));
      o.noise.roll_rad = units::degToRad(n->numberIn("roll_deg", 0.0, 45.0, 0.0));
      o.noise.speed_mps = n->numberIn("speed_mps", 0.0, 10.0, 0.0);
      o.noise.heading_rad = units::degToRad(n->numberIn("heading_deg", 0.0, 45.0, 0.0));
      o.noise.temperature_degC = n->numberIn("temperature_degC", 0.0, 10.0, 0.0);
      o.noise.salinity_psu = n->numberIn("salinity_psu", 0.0, 10.0, 0.0);
      o.noise.pressure_dbar = n->numberIn("pressure_dbar", 0.0, 100.0, 0.0);
    }
  }
  return plan;
}

MissionPlan loadMissionPlan(const std::string& file) { return parseMissionPlan(JsonReader::parseFile(file), file); }

GliderScenario resolveGliderScenario(const MissionPlan& plan, const VehicleProfile& profile) {
  GliderScenario sc = plan.glider;
  if (!plan.installed_kg.empty()) {
    checkInstalledKg(profile, plan.installed_kg, "installed_kg", {plan.file, 0, 0});
    const std::vector<MassItem> w = installedWeights(profile, plan.installed_kg);
    sc.extra_masses.insert(sc.extra_masses.begin(), w.begin(), w.end());
  }
  return sc;
}

Scenario resolveScenario(const MissionPlan& plan, const VehicleProfile& profile) {
  Scenario sc = plan.scenario;
  if (!plan.installed_kg.empty()) {
    checkInstalledKg(profile, plan.installed_kg, "installed_kg", {plan.file, 0, 0});
    const std::vector<MassItem> w = installedWeights(profile, plan.installed_kg);
    sc.extra_masses.insert(sc.extra_masses.begin(), w.begin(), w.end());
  }
  return sc;
}

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
