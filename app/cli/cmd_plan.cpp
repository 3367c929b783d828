// auvballast plan: pre-mission mode. What the last mission showed (an
// analysis report, or the history's latest analysis), the pieces installed
// now (flags or history) and the next mission's water (flags or the last
// mission's) -> which pieces to add or remove where (core/planning). This
// file only maps flags and history records; every number comes from core.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_context.h"
#include "commands.h"
#include "common/input_error.h"
#include "discrepancy/profile_update.h"
#include "history/ballasting_file.h"
#include "history/configuration_id.h"
#include "history/staleness.h"
#include "history/store.h"
#include "history/transaction.h"
#include "number_list.h"
#include "target_flags.h"
#include "planning/glider_ballast_plan.h"
#include "planning/plan_sources.h"
#include "planning/pre_mission_plan.h"
#include "planning/report_consistency.h"
#include "vehicle/json_reader.h"
#include "vehicle/vehicle_catalog.h"
#include "workflow/plan_inputs_from_history.h"

namespace auv::cli {
namespace {

struct PlanOpts {
  std::string vehicle, config, report, installed, temperature, salinity, depth, max_depth, latitude = "45",
      policy = "exact", sigma_factor = "1.645", json, history;
  bool optional_pieces = false, accept = false, no_save = false, no_surface_check = false;
  TargetFlags target;
};

// Gliders: the grams per bottle (or lead and C_VBD) from a report, for the
// report's target or the one given; the history is not involved.
int runGliderPlan(const PlanOpts& o, const VehicleProfile& v) {
  if (o.report.empty())
    throw InputError("report", "missing", "give --report REPORT.json from 'auvballast analyze' or 'model-check' of a glider log");
  GliderPlanInput in;
  in.report = JsonReader::parseFile(o.report);
  if (!o.installed.empty())
    in.installed_kg = parseNumberList(o.installed, v.points.size(), "installed",
                                      "the kg of ballast now at each point, in profile order");
  const analysis::GliderTargetRequest q = o.target.request();
  if (q.any()) in.target = targetFromReport(in.report, q, parseNumber(o.latitude, "latitude", "the latitude in degrees"));
  nlohmann::json j = planGliderBallast(v, in);
  j["sources"] = {{"analysis", o.report}};
  if (!o.json.empty()) writeJson(j, o.json);
  if (o.json != "-") std::cout << gliderPlanText(j);
  return 0;
}

// What the plan starts from, wherever it came from.
struct Sources {
  std::vector<double> installed_kg;
  std::optional<double> total_mass_kg;  // recorded vehicle mass with those pieces
  std::optional<RecordId> analysis_id;
  std::optional<TimePoint> measured_at;  // of the water the estimate holds in (history only)
  std::string report_name;
  nlohmann::json report;
};

PlannedWater plannedWater(const PlanOpts& o, const TrimEstimate& e, const Sources& s, std::string& source) {
  // The last mission's water unless the operator gives it.
  PlannedWater w = lastMissionWater(e, parseNumber(o.latitude, "latitude", "the latitude in degrees"));
  const bool any = !o.temperature.empty() || !o.salinity.empty() || !o.depth.empty();
  source = any ? "operator" : "last mission";
  if (o.temperature.empty()) {
    if (s.measured_at && temperatureIsStale(*s.measured_at, nowUtc())) {
      throw InputError("temperature",
                       "the last measured temperature (" + std::to_string(e.water.temperature_degC).substr(0, 6) +
                           " degC, " + toIsoUtc(*s.measured_at) + ") is older than one month (thesis \u00a75.5.3)",
                       "measure the water and give --temperature DEGC (and --salinity PSU)");
    }
  } else {
    w.temperature_degC = parseNumber(o.temperature, "temperature", "the next mission's water temperature in degC");
  }
  if (!o.salinity.empty()) w.salinity_psu = parseNumber(o.salinity, "salinity", "the next mission's practical salinity in PSU");
  if (!o.depth.empty()) w.depth_m = parseNumber(o.depth, "depth", "the next mission's operating depth in metres");
  return w;
}

int runPlan(const PlanOpts& o) {
  if (o.vehicle.empty()) throw InputError("vehicle", "missing", "give --vehicle ID (see 'auvballast vehicles')");
  VehicleProfile v = VehicleCatalog(vehiclesDir()).load(o.vehicle);
  if (v.kind == "glider") return runGliderPlan(o, v);
  if (o.config.empty()) throw InputError("config", "missing", "give --config ID (thesis xx-xx-xx, e.g. 1-2-3)");
  requireValidConfigurationId(o.config);
  PreMissionInput in;
  in.policy = planPolicyFromString(o.policy);
  in.use_optional_pieces = o.optional_pieces;
  in.sigma_factor = parseNumber(o.sigma_factor, "sigma-factor", "k of the safety margin k * sigma, e.g. 1.645");

  // The history is needed for whatever the flags do not give, and to record
  // the plan; what it gives comes through one core function (the wizard's too).
  std::unique_ptr<HistoryStore> store;
  HistoryPlanInputs h;
  const bool need_history = o.installed.empty() || o.report.empty();
  if (need_history || !o.no_save || o.accept) {
    store = std::make_unique<HistoryStore>(historyPath(o.history));
    h = planInputsFromHistory(*store, o.config, v, nowUtc());
    v = h.vehicle;
    if (!h.configuration_known && o.accept) {
      throw InputError("config", "'" + o.config + "' is not in the history '" + store->path() + "', so --accept has nothing to update",
                       "create the configuration first: 'auvballast first-mission --weighing FILE.json --config " + o.config +
                           " --history " + store->path() + "' (or crane flags instead of --weighing), then plan again");
    }
    if (!h.configuration_known && need_history) {
      throw InputError("config", "'" + o.config + "' is not in the history '" + store->path() + "'",
                       "give --installed and --report, or record the configuration first ('auvballast first-mission "
                       "... --config " + o.config + " --history FILE' or 'history --import-ballasting-file')");
    }
  }
  const std::size_t model_terms = h.model_terms;

  Sources s;
  s.total_mass_kg = h.total_mass_kg;
  if (!o.installed.empty()) {
    s.installed_kg = parseNumberList(o.installed, v.points.size(), "installed",
                                     "the kg of adjustment weight now at each point, in profile order");
  } else if (h.installed) {
    s.installed_kg = installedKg(*h.installed, v, o.config);
  } else {
    throw InputError("installed", "the history has no installed pieces for configuration " + o.config,
                     "give --installed FS,FP,AS,AP (kg at each point, profile order)");
  }
  if (!o.report.empty()) {
    s.report = JsonReader::parseFile(o.report);
    s.report_name = o.report;
    refuseUnknownReportKeys(s.report, s.report_name);
  } else {
    if (!h.analysis) {
      throw InputError("report", "the history has no analysis for configuration " + o.config,
                       "give --report analysis.json (from 'auvballast analyze', or record one with "
                       "'auvballast model-check --accept --config " + o.config + "')");
    }
    s.report = h.analysis->result;
    s.analysis_id = h.analysis->id;
    s.measured_at = h.analysis->at;
    s.report_name = "history analysis #" + std::to_string(h.analysis->id);
  }

  // An analysis without a physical estimate (e.g. imported from a thesis
  // ballasting file) still carries the deviations the classic table reads;
  // the mass then comes from the recorded total weight, as in the thesis.
  const PlanStart start = planStartFromReport(v, s.report, s.report_name, in.policy, s.total_mass_kg, h.measured_water);
  if (!start.physical && h.measured_water_at) s.measured_at = h.measured_water_at;
  in.estimate = start.estimate;
  in.classic_computed_imbalance_kg = start.classic_computed_imbalance_kg;
  in.installed_kg = s.installed_kg;

  std::string source;
  const PlannedWater operating = plannedWater(o, in.estimate, s, source);
  const double deepest = o.max_depth.empty() ? 0.0 : parseNumber(o.max_depth, "max-depth", "the deepest planned depth in metres");
  in.next = nextMissionWater(operating, deepest, source);
  if (o.no_surface_check) {
    std::erase_if(in.next.transit, [](const PlannedWater& w) { return w.depth_m == 0.0; });
  }
  const PreMissionPlan plan = planPreMission(v, in);
  nlohmann::json j = toJson(plan);
  j["config"] = o.config;
  j["sources"] = {{"analysis", s.report_name}, {"installed", o.installed.empty() ? "history" : "flags"},
                  {"water", source}};
  if (o.no_surface_check) j["warnings"].push_back("surface check disabled (--no-surface-check)");
  if (h.model_from_history)
    j["notes"].push_back("vehicle model from the history: " + std::to_string(model_terms) + " accepted model-check term(s), " +
                         std::to_string(h.model_calibrated) + " calibrated constant(s)");

  if (store && h.configuration_known && !o.no_save) {
    Transaction tx(store->database());
    Recommendation r;
    r.at = nowUtc();
    r.analysis_id = s.analysis_id;
    r.policy = toString(in.policy);
    r.recommendation = j;
    r.accepted = o.accept;
    const RecordId rid = store->addRecommendation(o.config, r);
    if (o.accept) {
      InstalledState st;
      st.installed_at = r.at;
      st.recommendation_id = rid;
      double added = 0.0;
      const std::vector<double> after = installedAfterPlan(s.installed_kg, plan);
      for (std::size_t i = 0; i < v.points.size(); ++i) {
        st.points.push_back({v.points[i].name, after[i], {}});
        added += plan.points[i].add_kg;
      }
      if (s.total_mass_kg) st.total_mass_kg = std::round((*s.total_mass_kg + added) * 1e4) / 1e4;
      st.note = "accepted pre-mission plan (" + r.policy + ")";
      store->addInstalledState(o.config, st);
    }
    tx.commit();
    j["history"] = {{"file", store->path()}, {"recommendation_id", rid}, {"accepted", o.accept}};
  }
  if (!o.json.empty()) writeJson(j, o.json);
  if (o.json != "-") {
    std::cout << toText(plan);
    if (j.contains("history")) {
      std::cout << "Recorded as recommendation #" << j["history"]["recommendation_id"].get<RecordId>() << " of "
                << o.config << (o.accept ? " (accepted: installed state updated)" : "") << "\n";
    }
  }
  return 0;
}

}  // namespace

Command addPlanCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("plan", "Pre-mission mode: last mission's estimate + installed pieces + next "
                                         "mission's water -> which weights to add or remove where");
  auto o = std::make_shared<PlanOpts>();
  cmd->add_option("--vehicle", o->vehicle, "Vehicle id (see 'auvballast vehicles') or profile .json");
  cmd->add_option("--config", o->config, "Configuration ID (thesis xx-xx-xx)");
  cmd->add_option("--report", o->report, "Analysis report JSON ('auvballast analyze --json'); default: the history's latest");
  cmd->add_option("--installed", o->installed, "Adjustment mass now at each point, kg, profile order (FS,FP,AS,AP); "
                                               "default: the history's latest installed state");
  cmd->add_option("--temperature", o->temperature, "Next mission's water temperature, degC (default: last mission's)");
  cmd->add_option("--salinity", o->salinity, "Next mission's practical salinity, PSU (default: last mission's)");
  cmd->add_option("--depth", o->depth, "Next mission's operating depth, m (default: last mission's)");
  cmd->add_option("--max-depth", o->max_depth, "Deepest planned depth, m, if deeper than the operating depth");
  o->target.add(cmd);
  cmd->add_option("--latitude", o->latitude, "Latitude for depth->pressure, deg")->capture_default_str();
  cmd->add_option("--policy", o->policy, "exact | half (about half the change) | classic (the thesis's table)")
      ->capture_default_str();
  cmd->add_option("--sigma-factor", o->sigma_factor, "k in the safety margin k * sigma")->capture_default_str();
  cmd->add_flag("--optional-pieces", o->optional_pieces, "Also use the kit's optional pieces (HUGIN: 0.5 kg)");
  cmd->add_flag("--no-surface-check", o->no_surface_check,
                "Do not require positive buoyancy at the surface (only at the planned depths)");
  cmd->add_option("--history", o->history,
                  "History database (default: $AUVBALLAST_HISTORY, else $XDG_DATA_HOME/auvballast/history.sqlite)");
  cmd->add_flag("--no-save", o->no_save, "Do not record the recommendation in the history");
  cmd->add_flag("--accept", o->accept, "Record the recommendation as accepted and installed");
  cmd->add_option("--json", o->json, "Write the JSON report here ('-' = stdout instead of text)");
  return {cmd, [o]() { return runPlan(*o); }};
}

}  // namespace auv::cli
