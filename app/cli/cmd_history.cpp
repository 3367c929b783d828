// auvballast history: what the ballasting history holds for a configuration,
// and the thesis's 'ballasting' file in and out (core/history). This file
// only maps flags; the database and the formats live in core.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli_context.h"
#include "commands.h"
#include "common/input_error.h"
#include "history/ballasting_file.h"
#include "history/configuration_id.h"
#include "history/default_location.h"
#include "history/export.h"
#include "history/store.h"

namespace fs = std::filesystem;

namespace auv::cli {

std::string historyPath(const std::string& flag) {
  // The same rule as the wizard (history/default_location.h).
  const std::string path = flag.empty() ? defaultHistoryPath() : flag;
  if (flag.empty()) ensureHistoryFolder(path);
  return path;
}

namespace {

struct HistoryOpts {
  std::string config, history, json, csv, import_file, export_file;
  bool check = false;
};

// `history --check`: the full integrity check, with the restore instructions.
int runCheck(HistoryStore& store) {
  const std::string result = store.integrityCheck();
  if (result == "ok") {
    std::cout << store.path() << ": integrity check ok; backup of the last save: " << store.database().backupPath()
              << (fs::exists(store.database().backupPath()) ? "" : " (none yet)") << "\n";
    return 0;
  }
  throw InputError("history database", "'" + store.path() + "' is damaged: " + result.substr(0, 400),
                   "restore the automatic backup: move '" + store.path() + "' aside and copy '" +
                       store.database().backupPath() + "' to '" + store.path() + "'");
}

std::string pointsText(const std::vector<InstalledPoint>& pts) {
  std::string s;
  char buf[96];
  for (const auto& p : pts) {
    std::snprintf(buf, sizeof buf, "%s%s %.2f kg", s.empty() ? "" : ", ", p.name.c_str(), p.mass_kg);
    s += buf;
  }
  return s;
}

std::string optText(const char* name, const std::optional<double>& v, const char* unit) {
  if (!v) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, " %s %g%s", name, *v, unit);
  return buf;
}

// One line per record, oldest first.
void printHistory(HistoryStore& store, const Configuration& c) {
  std::cout << "Configuration " << c.config_id << ": " << c.vehicle_name << " (" << c.vehicle_key << ")";
  if (!c.area.empty()) std::cout << ", area " << c.area;
  if (!c.payload_note.empty()) std::cout << ", " << c.payload_note;
  std::cout << "\n";
  for (const HistoryEvent& e : store.history(c.config_id)) {
    std::cout << "  " << toIsoUtc(e.at) << "  " << toString(e.kind) << " #" << e.id() << ":";
    if (const auto* w = std::get_if<WaterCondition>(&e.record)) {
      std::cout << optText("T", w->temperature_degC, " degC") << optText("S", w->salinity_psu, " PSU")
                << optText("depth", w->depth_m, " m") << optText("rho", w->density_kg_m3, " kg/m3") << " ("
                << w->source << ")";
    } else if (const auto* s = std::get_if<InstalledState>(&e.record)) {
      std::cout << " " << pointsText(s->points) << optText("total", s->total_mass_kg, " kg");
      if (s->recommendation_id) std::cout << " (recommendation #" << *s->recommendation_id << ")";
    } else if (const auto* r = std::get_if<Recommendation>(&e.record)) {
      std::cout << " policy " << r->policy << (r->accepted ? ", accepted" : ", not accepted");
      const auto& pts = r->recommendation.contains("recommendation") ? r->recommendation["recommendation"]["points"]
                                                                      : nlohmann::json::array();
      for (const auto& p : pts) {
        if (p.contains("add_kg") && p["add_kg"].is_number() && p["add_kg"].get<double>() != 0.0) {
          char buf[96];
          std::snprintf(buf, sizeof buf, " %s %+.2f kg;", p.value("name", std::string("?")).c_str(),
                        p["add_kg"].get<double>());
          std::cout << buf;
        }
      }
    } else if (const auto* a = std::get_if<AnalysisResult>(&e.record)) {
      for (const char* k : {"net_buoyancy_kg", kDepthDeviationKey, kPitchDeviationKey, kRollDeviationKey}) {
        if (a->result.contains(k) && a->result[k].is_number()) std::cout << " " << k << " " << a->result[k].get<double>();
      }
    } else if (const auto* m = std::get_if<Mission>(&e.record)) {
      std::cout << " " << m->file_path << " sha256 " << m->sha256.substr(0, 12);
    } else if (std::get_if<Weighing>(&e.record)) {
      std::cout << " weighing";
    }
    std::cout << std::endl;
  }
}

void writeText(const std::string& text, const std::string& path, const std::string& field) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(field, "cannot write '" + path + "'", "check the folder exists and is writable");
    out << text;
    if (!out.flush()) throw InputError(field, "write to '" + path + "' failed", "check free disk space");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw InputError(field, "cannot replace '" + path + "': " + ec.message(), "check permissions");
}

int runHistory(const HistoryOpts& o) {
  if (o.check) {
    HistoryStore store(historyPath(o.history));
    return runCheck(store);
  }
  if (o.import_file.empty() && o.config.empty()) {
    throw InputError("config", "missing", "give --config ID (thesis xx-xx-xx), or --import-ballasting-file FILE");
  }
  if (!o.config.empty()) requireValidConfigurationId(o.config);
  HistoryStore store(historyPath(o.history));
  if (!store.damage().empty()) {
    std::cerr << "WARNING: " << store.path() << " is damaged (" << store.damage()
              << "); it is listed read-only and saves are refused. Restore the backup " << store.database().backupPath()
              << " (see 'auvballast history --check')\n";
  }
  if (!o.import_file.empty()) {
    const BallastingFile file = readBallastingFile(o.import_file);
    const BallastingImport r = importBallastingFile(store, file, o.import_file);
    std::cout << "Imported " << r.rows_imported << " record(s) from " << o.import_file << " into " << store.path();
    if (r.rows_already_present) std::cout << " (" << r.rows_already_present << " already present)";
    std::cout << "\n";
    for (const auto& w : r.warnings) std::cout << "  WARNING: skipped " << w << "\n";
    if (o.config.empty()) return 0;
  }
  const auto c = store.configuration(o.config);
  if (!c) {
    throw InputError("config", "'" + o.config + "' is not in the history '" + store.path() + "'",
                     "check the ID, or create it with a first-mission run or --import-ballasting-file");
  }
  if (!o.export_file.empty()) {
    writeText(exportBallastingFile(store, o.config), o.export_file, "export-ballasting-file");
    if (o.export_file != "-") std::cout << "Wrote the ballasting file of " << o.config << " to " << o.export_file << "\n";
  }
  if (!o.csv.empty()) writeText(exportHistoryCsv(store, o.config), o.csv, "csv");
  if (!o.json.empty()) writeJson(exportHistoryJson(store, o.config), o.json);
  if (o.json != "-" && o.csv != "-" && o.export_file != "-") printHistory(store, *c);
  return 0;
}

}  // namespace

Command addHistoryCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("history", "List a configuration's ballasting history; import/export the thesis's "
                                            "ballasting file");
  auto o = std::make_shared<HistoryOpts>();
  cmd->add_option("--config", o->config, "Configuration ID (thesis xx-xx-xx, e.g. 1-2-3)");
  cmd->add_option("--history", o->history,
                  "History database (default: $AUVBALLAST_HISTORY, else $XDG_DATA_HOME/auvballast/history.sqlite)");
  cmd->add_option("--json", o->json, "Write the whole record as JSON here ('-' = stdout)");
  cmd->add_option("--csv", o->csv, "Write the whole record as CSV here ('-' = stdout)");
  cmd->add_option("--import-ballasting-file", o->import_file,
                  "Import a thesis 'ballasting' file (docs/formats/thesis-ballasting-file.md), all or nothing");
  cmd->add_option("--export-ballasting-file", o->export_file, "Write the configuration as a thesis 'ballasting' file");
  cmd->add_flag("--check", o->check,
                "Run SQLite's full integrity check on the history file (exit 2 with the restore instructions if damaged)");
  return {cmd, [o]() { return runHistory(*o); }};
}

}  // namespace auv::cli
