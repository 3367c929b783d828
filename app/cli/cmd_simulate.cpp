// auvballast simulate: fly a mission plan (or re-fly a recorded log) with the
// vehicle simulator and write the interchange CSV a vehicle would log. This
// file only maps flags; every number comes from core/sim.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_context.h"
#include "commands.h"
#include "common/input_error.h"
#include "common/units.h"
#include "missionlog/log_reader.h"
#include "number_list.h"
#include "resource_paths.h"
#include "sim/glider_model.h"
#include "sim/mission_plan.h"
#include "sim/replay.h"
#include "sim/sim_log.h"
#include "sim/water_from_log.h"
#include "vehicle/vehicle_catalog.h"

namespace auv::cli {
namespace {

using sim::BallastError;
using sim::SimTrace;
using sim::WaterColumn;

struct SimulateOpts {
  std::vector<std::string> replay;
  std::string cache_dir, vehicle, plan, out, installed, ballast_error, env, seed, interval, drive = "auto";
};

std::string requireVehicle(const SimulateOpts& o, const std::string& from_input, const std::string& input_name) {
  if (!o.vehicle.empty() && !from_input.empty() && o.vehicle != from_input &&
      std::filesystem::path(o.vehicle).stem() != from_input) {
    throw InputError("vehicle", "--vehicle " + o.vehicle + " but the " + input_name + " is for " + from_input,
                     "drop --vehicle or use the matching " + input_name);
  }
  if (!o.vehicle.empty()) return o.vehicle;
  if (!from_input.empty()) return from_input;
  throw InputError("vehicle", "missing", "give --vehicle ID (see 'auvballast vehicles')");
}

std::vector<double> installedKg(const SimulateOpts& o, const VehicleProfile& v) {
  return parseNumberList(o.installed, v.points.size(), "installed",
                         "the kg of adjustment weight at each point, in profile order");
}

BallastError ballastError(const SimulateOpts& o) {
  const auto e = parseNumberList(o.ballast_error, 0, "ballast-error",
                                 "NB_KG,X_MM[,Y_MM]: extra net buoyancy (kg, + = lighter) and CG shift (mm)");
  if (e.size() < 2 || e.size() > 3) {
    throw InputError("ballast-error", "expected 2 or 3 comma-separated values, got " + std::to_string(e.size()),
                     "give NB_KG,X_MM[,Y_MM], e.g. --ballast-error 3,5");
  }
  return {e[0], Eigen::Vector3d(units::mmToM(e[1]), e.size() > 2 ? units::mmToM(e[2]) : 0.0, 0.0)};
}

WaterColumn envWater(const std::string& env) {
  if (std::filesystem::path(env).extension() == ".csv") {
    ReadReport report;
    return sim::waterColumnFromLog(LogReaderRegistry::withBuiltinReaders().read(env, ReadOptions{}, report));
  }
  return sim::loadWaterFile(env);
}

void printSummary(const SimTrace& tr, const std::string& out) {
  std::printf("wrote %s: %zu rows, %.0f s\n", out.c_str(), tr.size(), tr.size() ? tr.time_s.back() - tr.time_s.front() : 0.0);
  std::printf("vehicle as flown: mass %.3f kg, net buoyancy %+.3f kg at the start (+ = light), CG - CB x %+.2f y %+.2f z %+.2f mm\n",
              tr.truth.mass_kg, tr.truth.net_buoyancy_start_n / units::g0, units::mToMm(tr.truth.cg_x_m),
              units::mToMm(tr.truth.cg_y_m), units::mToMm(tr.truth.cg_z_m));
  std::printf("energy %.1f Wh (hotel %.1f, propeller %.1f, thrusters %.1f, fins %.1f)\n", tr.energy_j / 3600.0,
              tr.hotel_energy_j / 3600.0, tr.prop_energy_j / 3600.0, tr.thruster_energy_j / 3600.0,
              tr.fins_energy_j / 3600.0);
}

// A glider plan ("yo" legs) on a glider profile.
int runGliderPlan(const SimulateOpts& o, const sim::MissionPlan& plan, const VehicleProfile& v) {
  if (v.kind != "glider") {
    throw InputError("legs", "yo legs are for gliders but '" + v.id + "' is an " + v.kind,
                     "use hover/depth legs for this vehicle");
  }
  const sim::GliderModel g = sim::loadGliderModel(v);
  sim::GliderScenario sc = sim::resolveGliderScenario(plan, v);
  if (!o.ballast_error.empty()) sc.ballast_error = ballastError(o);
  const SimTrace tr = sim::simulateGlider(g, plan.water, sc, plan.options);
  sim::SimLogInfo info{v.id, "plan", o.plan, plan.options.seed, 0, plan.installed_kg, {sim::latitudeMetadata(plan.water.latitudeDeg())}};
  sim::writeSimulatedLog(tr, info, o.out);
  printSummary(tr, o.out);
  return 0;
}

int runPlan(const SimulateOpts& o) {
  sim::MissionPlan plan = sim::loadMissionPlan(o.plan);
  const VehicleProfile v = VehicleCatalog(vehiclesDir()).load(requireVehicle(o, plan.vehicle, "plan"));
  if (!o.installed.empty()) plan.installed_kg = installedKg(o, v);
  if (!o.env.empty()) plan.water = envWater(o.env);
  if (!o.seed.empty()) {
    const double s = parseNumber(o.seed, "seed", "a whole number >= 0");
    if (!(s >= 0.0 && s < 9007199254740992.0 && s == std::floor(s))) {
      throw InputError("seed", "'" + o.seed + "' is not a whole number >= 0", "give e.g. --seed 42");
    }
    plan.options.seed = static_cast<std::uint64_t>(s);
  }
  if (!o.interval.empty()) {
    plan.options.trace_interval_s = parseNumber(o.interval, "interval", "the output interval in seconds");
    if (!(plan.options.trace_interval_s >= plan.options.dt_s && plan.options.trace_interval_s <= 3600.0)) {
      throw InputError("interval", "must be between the model step (" + std::to_string(plan.options.dt_s) +
                                       " s) and 3600 s",
                       "give e.g. --interval 1");
    }
  }
  if (plan.isGliderPlan()) return runGliderPlan(o, plan, v);
  if (v.kind == "glider") {
    throw InputError("legs", "'" + v.id + "' is a glider: it flies yo legs, not hover/depth legs",
                     "use legs of type \"yo\" (docs/formats/mission-plan.md)");
  }
  const sim::SimVehicle sv = sim::loadSimVehicle(v, app::resourceDir());
  sim::Scenario sc = sim::resolveScenario(plan, v);
  if (!o.ballast_error.empty()) sc.ballast_error = ballastError(o);
  sim::DepthAutopilotConfig ap = sv.autopilot;
  if (plan.anti_windup) ap.anti_windup = *plan.anti_windup;
  const SimTrace tr = sim::simulate(sv.model, ap, plan.water, sc, plan.options);
  sim::SimLogInfo info{v.id, "plan", o.plan, plan.options.seed, sv.model.thruster_count, plan.installed_kg, {sim::latitudeMetadata(plan.water.latitudeDeg())}};
  sim::writeSimulatedLog(tr, info, o.out);
  printSummary(tr, o.out);
  return 0;
}

int runReplay(const SimulateOpts& o) {
  ReadReport report;
  const MissionLog log = readLogArgument(o.replay, logReadOptions(o.cache_dir), report);
  const std::string replayName = o.replay.size() == 1 ? o.replay.front() : logArgumentLabel(o.replay);
  const std::string* logged_vehicle = log.metadataValue("vehicle");
  const VehicleProfile v =
      VehicleCatalog(vehiclesDir()).load(requireVehicle(o, logged_vehicle ? *logged_vehicle : "", "log"));
  if (v.kind == "glider") {
    throw InputError("replay", "replay of glider logs is not implemented",
                     "simulate the glider from a plan with yo legs instead");
  }
  const sim::SimVehicle sv = sim::loadSimVehicle(v, app::resourceDir());
  sim::ReplayOptions ro;
  ro.drive = sim::parseReplayDrive(o.drive);
  // The vehicle as its owner believes it to be: --installed, else what the
  // log says was installed. A simulated log's truth (its ballast error) is
  // deliberately not used: the differences are what a model check looks for.
  std::vector<double> installed;
  if (!o.installed.empty()) {
    installed = installedKg(o, v);
  } else if (const std::string* logged = log.metadataValue("installed_kg")) {
    installed = parseNumberList(*logged, v.points.size(), "installed_kg",
                                "the log's '# installed_kg:' line as kg per point, or give --installed");
  }
  if (!installed.empty()) ro.loading.extra_masses = sim::installedWeights(v, installed);
  if (!o.ballast_error.empty()) ro.loading.error = ballastError(o);
  if (!o.seed.empty() || !o.interval.empty()) {
    throw InputError(o.seed.empty() ? "interval" : "seed", "does not apply to --replay",
                     "a replay is noise-free and has one row per recorded row");
  }
  const WaterColumn water = o.env.empty() ? sim::waterColumnFromLog(log) : envWater(o.env);
  const sim::ReplayDrive drive = sim::resolveReplayDrive(sv.model, log, ro.drive);
  ro.drive = drive;
  const SimTrace tr = aboutFile(replayName, [&] { return sim::replay(sv.model, sv.autopilot, water, log, ro); });
  sim::SimLogInfo info{v.id, "replay", replayName, 0, sv.model.thruster_count, installed,
                       {{"replay_drive", sim::replayDriveName(drive)}}};
  sim::writeSimulatedLog(tr, info, o.out);
  if (!report.clean()) std::cout << report.summary() << "\n";
  std::printf("replayed %s driven by its %s\n", replayName.c_str(),
              drive == sim::ReplayDrive::Actuators ? "actuators (elevator, rudder, propeller)"
              : drive == sim::ReplayDrive::PitchCommands ? "pitch commands"
                                                         : "depth commands");
  printSummary(tr, o.out);
  return 0;
}

}  // namespace

Command addSimulateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "simulate", "Fly a mission plan (or re-fly a recorded log) and write the mission-log CSV a vehicle would log");
  auto o = std::make_shared<SimulateOpts>();
  cmd->add_option("--vehicle", o->vehicle,
                  "Vehicle id (see 'auvballast vehicles') or profile .json; default: the plan's or log's vehicle");
  cmd->add_option("--plan", o->plan, "Mission plan (docs/formats/mission-plan.md)");
  cmd->add_option("--replay", o->replay,
                  "Recorded mission log (file, or folder of a mission's files; repeatable) to re-fly with its own "
                  "actuators or commands");
  cmd->add_option("--cache-dir", o->cache_dir, kCacheDirHelp);
  cmd->add_option("--out", o->out, "Where to write the simulated log (interchange CSV)")->required();
  cmd->add_option("--installed", o->installed,
                  "Adjustment mass at each point, kg, profile order (e.g. FS,FP,AS,AP); overrides the plan's");
  cmd->add_option("--ballast-error", o->ballast_error,
                  "NB_KG,X_MM[,Y_MM]: the vehicle is really this much lighter (kg) and its CG this far off (mm)");
  cmd->add_option("--env", o->env,
                  "Water: a JSON water object ({\"cast\": [...]} or {\"density_kgm3\": ...}) or a log .csv with "
                  "depth/temperature/salinity; default: the plan's water, or the replayed log's CTD");
  cmd->add_option("--seed", o->seed, "Sensor-noise seed (same seed, same file); default: the plan's");
  cmd->add_option("--interval", o->interval, "Output interval, s; default: the plan's trace_interval_s");
  cmd->add_option("--drive", o->drive, "Replay: auto | actuators | pitch | depth")->capture_default_str();
  return {cmd, [o]() {
            if (o->plan.empty() == o->replay.empty()) {
              throw InputError(o->plan.empty() ? "plan" : "replay",
                               o->plan.empty() ? "missing" : "--plan and --replay together",
                               "give either --plan FILE or --replay LOG.csv");
            }
            return o->plan.empty() ? runReplay(*o) : runPlan(*o);
          }};
}

}  // namespace auv::cli
