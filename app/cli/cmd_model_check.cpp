// auvballast model-check: a mission log and a vehicle -> the post-mission
// analysis plus the model check (core/discrepancy): where the recording and
// the model disagree, which physics the model lacks, fitted and proven on
// held-out simulation error; --accept writes the accepted terms into a copy
// of the vehicle profile. This file only maps flags; every number comes from core.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <iostream>
#include <memory>

#include "analysis/analysis_report.h"
#include "analysis/mission_analysis.h"
#include "cli_context.h"
#include "commands.h"
#include "common/input_error.h"
#include "common/units.h"
#include "discrepancy/glider_ballast_answer.h"
#include "discrepancy/held_law_retest.h"
#include "discrepancy/model_check_report.h"
#include "discrepancy/profile_update.h"
#include "discrepancy/vehicle_check.h"
#include "history/store.h"
#include "history/configuration_id.h"
#include "history/timestamp.h"
#include "workflow/history_calibration.h"
#include "workflow/plan_inputs_from_history.h"
#include "missionlog/log_reader.h"
#include "number_list.h"
#include "planning/glider_ballast_plan.h"
#include "resource_paths.h"
#include "target_flags.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_writer.h"
#include "vehicle/vehicle_catalog.h"

namespace auv::cli {
namespace {

struct ModelCheckOpts {
  std::vector<std::string> log;
  std::string cache_dir, vehicle, json, out_profile, installed, bg_mm, cg_y_sigma_mm, terms, min_depth, config, history;
  bool accept = false;
  TargetFlags target;
};

int runModelCheck(const ModelCheckOpts& o) {
  if (o.vehicle.empty()) throw InputError("vehicle", "missing", "give --vehicle ID (see 'auvballast vehicles') or a profile .json");
  if (o.log.empty()) throw InputError("log", "missing", "give --log FILE or --log FOLDER (a mission log, e.g. the interchange CSV, or a folder of the vehicle's files)");
  const VehicleProfile v = VehicleCatalog(vehiclesDir()).load(o.vehicle);
  const std::string logName = logArgumentLabel(o.log);

  analysis::AnalysisOptions a;
  a.log_name = logName;
  a.glider_target = o.target.request();
  discrepancy::CheckSetup setup;
  if (!o.installed.empty()) {
    a.installed_kg = parseNumberList(o.installed, v.points.size(), "installed",
                                     "the kg of adjustment weight at each point during the mission, in profile order");
    setup.auv.installed_kg = a.installed_kg;
  }
  if (!o.bg_mm.empty()) a.bg_m = parseBgMm(o.bg_mm);  // the check holds the analysis's BG
  if (!o.cg_y_sigma_mm.empty()) {
    const double s = parseNumber(o.cg_y_sigma_mm, "cg-y-sigma-mm", "the CG y uncertainty of a roll test, in mm");
    if (!(s > 0.0)) throw InputError("cg-y-sigma-mm", "must be positive", "e.g. --cg-y-sigma-mm 0.2");
    setup.auv.cg_y_sigma_m = units::mmToM(s);
  }
  if (!o.min_depth.empty()) {
    const double z = parseNumber(o.min_depth, "min-depth", "the shallowest depth (m) a glider sample may come from");
    if (!(z >= 0.0)) throw InputError("min-depth", "must not be negative", "e.g. --min-depth 50");
    setup.glider.min_depth_m = z;
  }
  discrepancy::ModelCheckOptions mo;
  if (!o.terms.empty()) {
    std::string t = o.terms;
    for (std::size_t p = 0; p <= t.size();) {
      const std::size_t q = std::min(t.find(',', p), t.size());
      const std::string id = t.substr(p, q - p);
      if (!discrepancy::findTerm(id))
        throw InputError("terms", "'" + id + "' is not a model-check term",
                         "use ids such as hull_compressibility, thermal_expansion, mass_drift, pitch_sensor_bias");
      mo.only_terms.push_back(id);
      p = q + 1;
    }
  }

  // With a configuration: what flew (the history's installed pieces unless
  // given) and its latest analysed mission, whose known weight change
  // calibrates the hydrodynamics jointly with this one (issue 11 item 3).
  std::unique_ptr<HistoryStore> store;
  if (!o.config.empty()) {
    requireValidConfigurationId(o.config);
    store = std::make_unique<HistoryStore>(historyPath(o.history));
    addConfigurationHistory(*store, o.config, v, nowUtc(), a);
    setup.auv.installed_kg = a.installed_kg;
  }

  ReadReport readReport;
  const MissionLog log = readLogArgument(o.log, logReadOptions(o.cache_dir), readReport);
  const analysis::AnalysisReport r = aboutFile(logArgumentLabel(o.log), [&] { return analysis::analyzeMission(log, v, a); });
  nlohmann::json j = analysis::toJson(r);
  setup.analysis = &r;  // an AUV's check holds this analysis's calibration, in its water
  const std::unique_ptr<discrepancy::CheckModel> model = aboutFile(
      logArgumentLabel(o.log), [&] { return discrepancy::makeCheckModel(log, v, app::resourceDir(), setup); });
  discrepancy::ModelCheckResult mc =
      aboutFile(logArgumentLabel(o.log), [&] { return discrepancy::runModelCheck(*model, mo); });
  discrepancy::followFoundPitchBias(log, v, r, mc);
  discrepancy::mergeIntoAnalysisJson(j, mc, o.accept);
  if (!readReport.clean()) j["model_check"]["import"] = readReport.summary();
  const auto* glider = dynamic_cast<const discrepancy::GliderCheckModel*>(model.get());
  if (glider && std::isfinite(r.target_density_kgm3)) {
    // The answer with the vehicle as the check found it, in the same target
    // water the analysis resolved.
    const analysis::GliderTarget target{r.target_density_kgm3, r.target_pressure_dbar, r.target_temperature_degC,
                                        std::numeric_limits<double>::quiet_NaN(), r.target_basis};
    discrepancy::mergeGliderAnswer(j, discrepancy::gliderBallastAnswer(*glider, mc, target));
    std::string why_not;
    try {
      j["recommendation"] = planGliderBallast(v, {j, a.installed_kg, std::nullopt});
    } catch (const InputError& e) {
      j["recommendation"] = nullptr;
      j["recommendation_unavailable"] = e.what();
    }
  }

  if (o.accept) {
    const std::string out = o.out_profile.empty() ? v.id + ".model-check.json" : o.out_profile;
    const bool anything = !mc.missing_physics.empty() || discrepancy::hasCalibrationToWrite(mc);
    if (!anything) {
      j["model_check"]["profile_written"] = nullptr;
    } else {
      // The whole vehicle, companion sections (e.g. HUGIN's hydrodynamics
      // from resources/sim) included: the copy is read on its own later.
      const nlohmann::json doc = profileToJson(v);
      const nlohmann::json written = discrepancy::profileWithAcceptedTerms(doc, v, mc, logName);
      writeJson(written, out);
      j["model_check"]["profile_written"] = out;
      if (store) {
        // Also the configuration's model in the history, from which 'plan'
        // and the wizard take the vehicle from now on.
        ModelTerms m;
        m.at = nowUtc();
        m.model = {{"log", logName}, {"accepted", written["model_check"]["accepted"]}, {"profile", written}};
        if (written["model_check"].contains("calibrated")) m.model["calibrated"] = written["model_check"]["calibrated"];
        store->addModelTerms(o.config, m);
        j["model_check"]["history_config"] = o.config;
      }
    }
    if (store) {
      // The checked mission's analysis (calibrated with the history's
      // missions): 'plan --config' plans from it, the next mission
      // calibrates with its steady segments.
      AnalysisResult rec;
      rec.at = nowUtc();
      rec.result = j;
      j["model_check"]["history_analysis_id"] = store->addAnalysisResult(o.config, rec);
    }
  }
  if (!o.json.empty()) writeJson(j, o.json);
  if (o.json != "-") {
    if (!readReport.clean()) std::cout << readReport.summary() << "\n";
    std::cout << analysis::toText(r) << "\n" << discrepancy::toText(mc);
    if (j["model_check"].contains("estimate_source") && j["net_buoyancy_kg"].is_number())
      std::printf("Ballast state for the plan: net buoyancy %+.3f +- %.3f kg - %s\n", j["net_buoyancy_kg"].get<double>(),
                  j.value("net_buoyancy_sigma_kg", 0.0), j["model_check"]["estimate_source"].get<std::string>().c_str());
    if (j.contains("model_check") && j["model_check"].contains("glider_ballast")) {
      const auto& g = j["model_check"]["glider_ballast"];
      std::printf("Glider, jointly with the accepted terms: add %+.0f +- %.0f g for neutral (pump at zero) at the target\n",
                  g["mass_to_add_g"].get<double>(), g.value("mass_to_add_sigma_g", 0.0));
      if (g.value("mass_drift_g_per_h", 0.0) != 0.0)
        std::printf("  mass drift %+.1f g/h (carried to the end of the log: %+.0f g; carry it to the deployment day)\n",
                    g["mass_drift_g_per_h"].get<double>(), g["mass_change_at_end_g"].get<double>());
      if (j["recommendation"].is_object()) std::cout << gliderPlanText(j["recommendation"]);
    }
    if (o.accept) {
      if (j["model_check"]["profile_written"].is_null())
        std::cout << "Nothing accepted: no profile written.\n";
      else
        std::cout << "Accepted terms and identified calibration constants written to "
                  << j["model_check"]["profile_written"].get<std::string>()
                  << " (use it as --vehicle to fly and analyse with them).\n";
    }
  }
  return 0;
}

}  // namespace

Command addModelCheckCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "model-check",
      "Mission log -> analysis plus the model check: where the model and the recording differ, the physics it lacks, "
      "fitted and proven on held-out simulation error");
  auto o = std::make_shared<ModelCheckOpts>();
  cmd->add_option("--vehicle", o->vehicle, "Vehicle id (see 'auvballast vehicles') or profile .json")->required();
  cmd->add_option("--log", o->log,
                  "Mission log: a file (interchange CSV or a vehicle's own format) or a folder of a mission's files; "
                  "repeat for several files")
      ->required();
  cmd->add_option("--cache-dir", o->cache_dir, kCacheDirHelp);
  cmd->add_option("--json", o->json, "Write the JSON report (analysis + missing_physics) here ('-' = stdout instead of text)");
  cmd->add_flag("--accept", o->accept,
                "Write the accepted terms and the identified calibration constants into a complete copy of the vehicle "
                "profile (hydrodynamics included)");
  cmd->add_option("--config", o->config,
                  "Configuration ID: the pieces that flew, BG and the pitch sensor's prior default to its installed state, "
                  "roll test and dock level check, the analysis calibrates jointly "
                  "with its latest analysed mission; with --accept the accepted terms become its vehicle model and this "
                  "analysis is recorded for 'plan --config'");
  cmd->add_option("--history", o->history, "History database (default: the user's, as for 'plan')");
  cmd->add_option("--out-profile", o->out_profile, "Where --accept writes the profile copy (default <id>.model-check.json)");
  cmd->add_option("--installed", o->installed,
                  "AUV: adjustment mass at each point during the logged mission, kg, profile order");
  cmd->add_option("--bg-mm", o->bg_mm,
                  "AUV: CG below CB from an inclining/roll test, mm (as for 'analyze'): with BG known a pitch sensor "
                  "bias can be told from the ballast state");
  cmd->add_option("--cg-y-sigma-mm", o->cg_y_sigma_mm,
                  "AUV: CG y is known from a roll test to this sigma (mm); lets a roll-sensor bias be told from CG y");
  cmd->add_option("--terms", o->terms, "Only try these library terms (comma-separated ids)");
  o->target.add(cmd);
  cmd->add_option("--min-depth", o->min_depth, "Gliders: use samples deeper than this, m (default 10)");
  return {cmd, [o]() { return runModelCheck(*o); }};
}

}  // namespace auv::cli
