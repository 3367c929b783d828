// auvballast analyze: a mission log and a vehicle -> segments, errors, water
// and the estimated net buoyancy and CG offset (core/analysis). This file only
// maps flags; every number comes from core.
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "analysis/analysis_report.h"
#include "analysis/mission_analysis.h"
#include "cli_context.h"
#include "commands.h"
#include "common/input_error.h"
#include "common/units.h"
#include "history/configuration_id.h"
#include "history/store.h"
#include "history/timestamp.h"
#include "missionlog/log_reader.h"
#include "number_list.h"
#include "planning/glider_ballast_plan.h"
#include "planning/recommend_from_analysis.h"
#include "target_flags.h"
#include "vehicle/vehicle_catalog.h"
#include "workflow/history_calibration.h"

namespace auv::cli {
namespace {

struct AnalyzeOpts {
  std::vector<std::string> log;
  std::string cache_dir, vehicle, installed, bg_mm, coefficient_sigma, pitch_alignment_sigma, json, config, history;
  TargetFlags target;
  bool no_classic = false;
  bool transients = false;
};

int runAnalyze(const AnalyzeOpts& o) {
  if (o.vehicle.empty()) throw InputError("vehicle", "missing", "give --vehicle ID (see 'auvballast vehicles') or a profile .json");
  if (o.log.empty()) throw InputError("log", "missing", "give --log FILE or --log FOLDER (a mission log, e.g. the interchange CSV, or a folder of the vehicle's files)");
  const VehicleProfile v = VehicleCatalog(vehiclesDir()).load(o.vehicle);

  analysis::AnalysisOptions a;
  a.log_name = logArgumentLabel(o.log);
  if (!o.installed.empty())
    a.installed_kg = parseNumberList(o.installed, v.points.size(), "installed",
                                     "the kg of adjustment weight at each point during the mission, in profile order");
  if (!o.bg_mm.empty()) a.bg_m = parseBgMm(o.bg_mm);
  a.glider_target = o.target.request();
  if (!o.coefficient_sigma.empty()) {
    const double r = parseNumber(o.coefficient_sigma, "coefficient-sigma",
                                 "the 1-sigma relative uncertainty of the profile's hydrodynamic derivatives");
    if (!(r >= 0.0 && r <= 1.0))
      throw InputError("coefficient-sigma", "must be a fraction between 0 and 1", "e.g. --coefficient-sigma 0.02 for derivatives known to 2 %");
    a.coefficient_rel_sigma = r;
  }
  std::optional<double> alignment_sigma_deg;
  if (!o.pitch_alignment_sigma.empty()) {
    const double s = parseNumber(o.pitch_alignment_sigma, "pitch-alignment-sigma-deg",
                                 "the 1-sigma uncertainty of the pitch sensor's alignment, deg");
    if (!(s >= 0.0 && s <= 5.0))
      throw InputError("pitch-alignment-sigma-deg", "must be between 0 and 5 deg",
                       "e.g. --pitch-alignment-sigma-deg 0.1 after a level check on the dock, 0 to read the pitch as true");
    alignment_sigma_deg = s;
  }
  a.classic = !o.no_classic;
  a.use_transients = o.transients;

  // With a configuration: the pieces that flew (unless given), its roll
  // test's BG, its pitch sensor level check and its latest analysed
  // mission, whose known weight change calibrates jointly with this one.
  // Read only: model-check --config and the wizard record missions.
  if (!o.config.empty()) {
    requireValidConfigurationId(o.config);
    HistoryStore store(historyPath(o.history));
    addConfigurationHistory(store, o.config, v, nowUtc(), a);
  }
  if (alignment_sigma_deg) a.pitch_alignment_sigma_deg = *alignment_sigma_deg;  // over the configuration's level check

  ReadReport readReport;
  const MissionLog log = readLogArgument(o.log, logReadOptions(o.cache_dir), readReport);
  analysis::AnalysisReport r = aboutFile(logArgumentLabel(o.log), [&] { return analysis::analyzeMission(log, v, a); });
  if (!readReport.clean()) {
    r.warnings.insert(r.warnings.begin(), "the log had problems on import (" + std::to_string(readReport.totalProblems()) +
                                              "); see the import summary");
    r.details["import"] = {{"format", readReport.format},
                           {"rows_kept", readReport.rows_kept},
                           {"rows_skipped", readReport.rows_skipped},
                           {"cells_blanked", readReport.cells_blanked},
                           {"summary", readReport.summary()}};
  }
  nlohmann::json report = analysis::toJson(r);
  std::string why_not;
  report["recommendation"] = recommendFromAnalysis(v, report, a.installed_kg, why_not);
  if (report["recommendation"].is_null()) report["recommendation_unavailable"] = why_not;
  if (!o.json.empty()) writeJson(report, o.json);
  if (o.json != "-") {
    if (!readReport.clean()) std::cout << readReport.summary() << "\n";
    std::cout << analysis::toText(r);
    if (v.kind == "glider" && !report["recommendation"].is_null()) {
      std::cout << gliderPlanText(report["recommendation"]);
    } else if (report["recommendation"].is_null()) {
      std::cout << "No weight change recommended: " << why_not << "\n";
    } else {
      std::cout << "Recommended change for the next mission in the same water (see 'auvballast plan' for others):\n";
      for (const auto& p : report["recommendation"]["points"]) {
        std::printf("  %-18s %+6.2f kg\n", p.value("label", p.value("name", "")).c_str(), p.value("add_kg", 0.0));
      }
    }
  }
  return 0;
}

}  // namespace

Command addAnalyzeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "analyze", "Mission log -> operating segments, depth/pitch/roll errors, water, net buoyancy and CG offset");
  auto o = std::make_shared<AnalyzeOpts>();
  cmd->add_option("--vehicle", o->vehicle, "Vehicle id (see 'auvballast vehicles') or profile .json")->required();
  cmd->add_option("--log", o->log,
                  "Mission log: a file (interchange CSV or a vehicle's own format) or a folder of a mission's files; "
                  "repeat for several files")
      ->required();
  cmd->add_option("--cache-dir", o->cache_dir, kCacheDirHelp);
  cmd->add_option("--installed", o->installed,
                  "Adjustment mass at each point during the logged mission, kg, profile order (e.g. FS,FP,AS,AP)");
  cmd->add_option("--bg-mm", o->bg_mm,
                  "CG below CB from an inclining/roll test, mm: turns the static roll into a CG y offset");
  o->target.add(cmd);
  cmd->add_option("--coefficient-sigma", o->coefficient_sigma,
                  "AUVs: prior 1-sigma of each group of the profile's hydrodynamic derivatives in the calibration "
                  "(default 0.30 with the Munk structure unknown; 0.02 once known, e.g. from a tow tank)");
  cmd->add_option("--pitch-alignment-sigma-deg", o->pitch_alignment_sigma,
                  "AUVs: prior 1-sigma of the pitch sensor's bias, which the calibration finds beside the ballast "
                  "state (calibration id pitch_sensor_bias; default 1 deg, or the --config's level check; 0 = the "
                  "sensor is aligned)");
  cmd->add_option("--config", o->config,
                  "AUVs: configuration ID in the history: the pieces that flew, BG and the pitch sensor's prior default "
                  "to its installed state, roll test and level check, and the analysis calibrates jointly with its "
                  "latest analysed mission (the known weight change between them; "
                  "details.auv_estimate.history_segments_used). Nothing is written");
  cmd->add_option("--history", o->history, "History database for --config (default: the user's, as for 'plan')");
  cmd->add_flag("--no-classic", o->no_classic, "Skip the thesis's App. D checks (reported under details.classic)");
  cmd->add_flag("--transients", o->transients,
                "AUVs: also fit the depth-step and propeller-speed transients through the simulator, jointly with "
                "the steady legs (details.transient_windows). For logs of 5 Hz or faster: at 1 Hz the replay misses "
                "command steps and the CG x sigma is too narrow");
  cmd->add_option("--json", o->json, "Write the JSON report here ('-' = stdout instead of text)");
  return {cmd, [o]() { return runAnalyze(*o); }};
}

}  // namespace auv::cli
