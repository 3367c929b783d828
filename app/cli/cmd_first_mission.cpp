#include <iostream>
#include <memory>
#include <optional>

#include "cli_context.h"
#include "commands.h"
#include "common/input_error.h"
#include "firstmission/crane_weighing_file.h"
#include "firstmission/hugin_first_mission.h"
#include "firstmission/slocum_first_mission.h"
#include "history/first_mission_record.h"
#include "history/configuration_id.h"
#include "history/store.h"
#include "history/timestamp.h"
#include "history/transaction.h"
#include "weighing/tank_weighing_file.h"
#include "number_list.h"
#include "vehicle/vehicle_catalog.h"
#include "vehicle/installed_check.h"
#include "vehicle/json_reader.h"

namespace auv::cli {
namespace {

struct FirstMissionOpts {
  std::string vehicle, scales, total, rope_x, rope_y, installed, temperature, salinity, depth = "0",
      latitude = "45", json, policy = "exact", weighing, config, history;
  bool optional_pieces = false;
};

// What a run computed plus what the history records about it.
struct FirstMissionRun {
  FirstMissionReport report;
  VehicleProfile vehicle;
  nlohmann::json inputs;              // the weighing as given (file or flags)
  std::vector<double> installed_kg;   // on the vehicle while it was weighed (crane)
};

PlannedWater plannedWater(const FirstMissionOpts& o) {
  if (o.temperature.empty()) throw InputError("temperature", "missing", "give --temperature DEGC of the mission water");
  if (o.salinity.empty()) throw InputError("salinity", "missing", "give --salinity PSU of the mission water");
  PlannedWater w;
  w.temperature_degC = parseNumber(o.temperature, "temperature", "the water temperature in degC");
  w.salinity_psu = parseNumber(o.salinity, "salinity", "the practical salinity in PSU");
  w.depth_m = parseNumber(o.depth, "depth", "the planned operating depth in metres");
  w.latitude_deg = parseNumber(o.latitude, "latitude", "the latitude in degrees");
  return w;
}

BallastPolicy parsePolicy(const std::string& p) {
  if (p == "exact") return BallastPolicy::Exact;
  if (p == "half") return BallastPolicy::HalfWay;
  throw InputError("policy", "unknown policy '" + p + "'", "use exact or half");
}

FirstMissionReport runCrane(const VehicleProfile& v, const FirstMissionOpts& o) {
  if (o.scales.empty()) throw InputError("scales", "missing", "give --scales FS,FP,AS,AP (kg at the four crane scales)");
  if (o.total.empty()) throw InputError("total", "missing", "give --total KG (the hook scale reading)");
  if (o.rope_x.empty()) throw InputError("rope-x", "missing", "give --rope-x FORE_M,AFT_M (rope stations in metres)");
  CraneFirstMissionInput in;
  const auto s = parseNumberList(o.scales, 4, "scales", "four kg readings FS,FP,AS,AP");
  std::copy(s.begin(), s.end(), in.weighing.scales_kg.begin());
  in.weighing.total_kg = parseNumber(o.total, "total", "the hook scale reading in kg");
  const auto rx = parseNumberList(o.rope_x, 2, "rope-x", "FORE_M,AFT_M in metres from the vehicle origin");
  in.weighing.rope_x_fore_m = rx[0];
  in.weighing.rope_x_aft_m = rx[1];
  // Defaults for the weighing rig come from the profile's "weighing" section.
  if (v.sections.contains("weighing")) {
    const JsonReader w(v.sections["weighing"], v.file, "weighing");
    in.weighing.rope_y_m = w.number("rope_y_m", in.weighing.rope_y_m);
    in.weighing.scale_resolution_kg = w.number("scale_resolution_kg", in.weighing.scale_resolution_kg);
    in.weighing.sum_tolerance_kg = w.number("sum_tolerance_kg", in.weighing.sum_tolerance_kg);
  }
  if (!o.rope_y.empty()) in.weighing.rope_y_m = parseNumber(o.rope_y, "rope-y", "the lateral rope offset in metres");
  if (!o.installed.empty()) {
    in.installed_kg = parseNumberList(o.installed, v.points.size(), "installed",
                                      "the kg of adjustment weight now at each point, in profile order");
  }
  in.water = plannedWater(o);
  in.use_optional_pieces = o.optional_pieces;
  in.policy = parsePolicy(o.policy);
  return craneFirstMission(v, in);
}

FirstMissionRun runCraneFlags(const FirstMissionOpts& o) {
  if (o.vehicle.empty()) throw InputError("vehicle", "missing", "give --vehicle ID (see 'auvballast vehicles')");
  // Members set one by one: GCC 12 destroys an aggregate's members twice when
  // an initializer throws (the profile loader's InputError).
  FirstMissionRun run;
  run.vehicle = VehicleCatalog(vehiclesDir()).load(o.vehicle);
  run.report = runCrane(run.vehicle, o);
  run.inputs = {{"method", "crane"}, {"vehicle", run.vehicle.id}, {"scales_kg", o.scales}, {"total_kg", o.total},
                {"rope_x_m", o.rope_x}, {"installed_kg", o.installed}, {"source", "command line"}};
  if (!o.installed.empty()) run.installed_kg = parseNumberList(o.installed, run.vehicle.points.size(), "installed", "kg");
  return run;
}

FirstMissionRun runWeighingFile(const FirstMissionOpts& o) {
  const nlohmann::json doc = JsonReader::parseFile(o.weighing);
  const std::string method = JsonReader(doc, o.weighing).text("method");
  const std::string vehicle = JsonReader(doc, o.weighing).text("vehicle");
  if (!o.vehicle.empty() && o.vehicle != vehicle) {
    throw InputError("vehicle", "--vehicle " + o.vehicle + " but the weighing file is for " + vehicle,
                     "drop --vehicle or use the matching weighing file");
  }
  FirstMissionRun run;
  run.vehicle = aboutFile(o.weighing, [&] { return VehicleCatalog(vehiclesDir()).load(vehicle); });
  run.inputs = doc;
  const VehicleProfile& v = run.vehicle;
  if (method == "crane") {
    CraneWeighingFile f = loadCraneWeighingFile(o.weighing);
    if (!f.input.installed_kg.empty()) checkInstalledKg(v, f.input.installed_kg, "installed_kg", {o.weighing, 0, 0});
    if (!o.policy.empty()) f.input.policy = parsePolicy(o.policy);
    if (o.optional_pieces) f.input.use_optional_pieces = true;
    run.installed_kg = f.input.installed_kg;
    run.report = aboutFile(o.weighing, [&] { return craneFirstMission(v, f.input); });
    return run;
  }
  if (method == "tank") {
    const TankWeighing tank = loadTankWeighing(o.weighing);
    run.report = aboutFile(o.weighing, [&] { return slocumFirstMission(v, tank); });
    return run;
  }
  throw InputError("method", "weighing method '" + method + "' is not supported",
                   "use \"crane\" (or \"tank\" for gliders)", {o.weighing, 0, 0});
}

// Creates the configuration (refused if the ID exists) and records the
// weighing, its water, the recommendation and the pieces on the vehicle while
// it was weighed, in one transaction, as the wizard's first-mission save does;
// `plan --config ID` starts from these records.
void saveToHistory(const FirstMissionOpts& o, const FirstMissionRun& run) {
  HistoryStore store(historyPath(o.history));
  const TimePoint now = nowUtc();
  const FirstMissionReport& r = run.report;
  Transaction tx(store.database());
  if (store.configuration(o.config)) {
    throw InputError("config", "'" + o.config + "' already exists in the history '" + store.path() + "'",
                     "choose a new configuration ID (thesis xx-xx-xx); see 'auvballast history --config " + o.config + "'");
  }
  Configuration c;
  c.config_id = o.config;
  c.vehicle_key = run.vehicle.id;
  c.vehicle_name = run.vehicle.name;
  c.created_at = now;
  store.addConfiguration(c);
  FirstMissionRecord record;
  record.tank = r.method == "tank";
  record.inputs = run.inputs;
  record.results = toJson(r);
  record.temperature_degC = r.temperature_degC;
  record.salinity_psu = r.salinity_psu;
  record.depth_m = r.depth_m;
  record.density_kg_m3 = r.density_kgm3;
  record.policy = record.tank ? "tank" : o.policy;
  const RecordId rid = recordFirstMission(store, o.config, record, now);
  if (r.method == "crane") {
    InstalledState st;
    st.installed_at = now;
    st.recommendation_id = rid;
    for (std::size_t i = 0; i < run.vehicle.points.size(); ++i) {
      st.points.push_back({run.vehicle.points[i].name, i < run.installed_kg.size() ? run.installed_kg[i] : 0.0, {}});
    }
    st.total_mass_kg = r.weight_kg;
    st.note = "as weighed (first mission)";
    store.addInstalledState(o.config, st);
  }
  tx.commit();
  std::cerr << "Recorded configuration " << o.config << " in " << store.path()
            << " (weighing, water, recommendation" << (r.method == "crane" ? ", installed pieces as weighed" : "")
            << ")\n";
}

}  // namespace

Command addFirstMissionCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("first-mission",
                                 "Weighing + planned water -> which weights to put where before the first mission");
  auto o = std::make_shared<FirstMissionOpts>();
  cmd->add_option("--vehicle", o->vehicle,
                  "Vehicle id (see 'auvballast vehicles') or profile .json; optional with --weighing");
  cmd->add_option("--scales", o->scales, "Crane: kg at the fore-starboard, fore-port, aft-starboard, aft-port scales");
  cmd->add_option("--total", o->total, "Crane: kg at the hook scale (whole vehicle)");
  cmd->add_option("--rope-x", o->rope_x, "Crane: FORE_M,AFT_M rope stations, metres from the vehicle origin (x fwd)");
  cmd->add_option("--rope-y", o->rope_y, "Crane: lateral offset of the rope ends, metres (default from profile, 0.25)");
  cmd->add_option("--installed", o->installed, "Adjustment mass now at each point, kg, profile order (FS,FP,AS,AP)");
  cmd->add_option("--weighing", o->weighing,
                  "Weighing file instead of flags: crane (docs/formats/crane-weighing.md) or tank "
                  "(docs/formats/slocum-tank-weighing.md)");
  cmd->add_option("--temperature", o->temperature, "Mission water temperature, degC");
  cmd->add_option("--salinity", o->salinity, "Mission water practical salinity, PSU");
  cmd->add_option("--depth", o->depth, "Planned operating depth, m (density includes pressure)")->capture_default_str();
  cmd->add_option("--latitude", o->latitude, "Latitude for depth->pressure, deg")->capture_default_str();
  cmd->add_option("--policy", o->policy, "exact | half (apply about half the change; never ends negative)")
      ->capture_default_str();
  cmd->add_flag("--optional-pieces", o->optional_pieces, "Also use the kit's optional pieces (HUGIN: 0.5 kg)");
  cmd->add_option("--json", o->json, "Write the JSON report here ('-' = stdout instead of text)");
  cmd->add_option("--config", o->config,
                  "Create this configuration (thesis xx-xx-xx) in the history and record the weighing, water, "
                  "recommendation and installed pieces, so 'plan --config' can start from it");
  cmd->add_option("--history", o->history,
                  "History database for --config (default: $AUVBALLAST_HISTORY, else "
                  "$XDG_DATA_HOME/auvballast/history.sqlite)");
  return {cmd, [o]() {
            if (!o->config.empty()) requireValidConfigurationId(o->config);
            if (o->config.empty() && !o->history.empty()) {
              throw InputError("history", "--history without --config records nothing",
                               "add --config ID to create that configuration in the history");
            }
            const FirstMissionRun run = o->weighing.empty() ? runCraneFlags(*o) : runWeighingFile(*o);
            if (!o->config.empty()) saveToHistory(*o, run);
            if (!o->json.empty()) writeJson(toJson(run.report), o->json);
            if (o->json != "-") std::cout << toText(run.report);
            return 0;
          }};
}

}  // namespace auv::cli
