#pragma once
// What every subcommand needs from the program around it: where the bundled
// resources are and how to write results. Keeps the command files free of
// environment lookups.
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "missionlog/mission_log.h"
#include "missionlog/read_report.h"

#include "missionlog/read_options.h"

#include "common/input_error.h"

namespace auv::cli {

std::string vehiclesDir();  // see app/common/resource_paths.h

// Writes pretty JSON to `path` ("-" = stdout). Throws InputError if it cannot.
void writeJson(const nlohmann::json& j, const std::string& path);

// How the commands that take --log read it: `--cache-dir DIR` is where
// Slocum binary files whose sensor list is factored out find their cache.
ReadOptions logReadOptions(const std::string& cacheDir);
inline constexpr const char* kCacheDirHelp =
    "Folder of Slocum sensor-list caches (<crc>.cac or .ccc) for binary .dbd/.ebd/.sbd/.tbd/... logs; searched "
    "before the log's own folder and the per-user cache (~/.cache/auvballast/slocum-cache)";

// `--log` as given: files and folders, the flag repeatable (`--log DIR`,
// `--log a.dbd --log a.ebd`), read as one mission by core readMission
// (missionlog/mission_files.h).
MissionLog readLogArgument(const std::vector<std::string>& logs, const ReadOptions& options, ReadReport& report);
// The name of the log(s) in reports: "p1710100.nc", "raw", "a.dbd and 1 more".
std::string logArgumentLabel(const std::vector<std::string>& logs);

// Runs `f`, a computation on the content of `file` (a log, a weighing file).
// Its refusals about that content ("no usable depth channel") carry no file;
// they are given `file` so every refusal names its file. Refusals about flags
// keep naming the flag.
template <class F>
auto aboutFile(const std::string& file, F&& f) -> decltype(f()) {
  static const std::set<std::string> flags = {"installed", "bg-mm", "target-density", "coefficient-sigma", "drive",
                                              "config", "terms", "min-depth", "cg-y-sigma-mm", "dt_s"};
  try {
    return f();
  } catch (const InputError& e) {
    if (!e.where().file.empty() || flags.count(e.field())) throw;
    throw InputError(e.field(), e.problem(), e.fix(), {file, 0, 0});
  }
}

}  // namespace auv::cli
