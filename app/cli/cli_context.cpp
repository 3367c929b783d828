#include "cli_context.h"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "common/input_error.h"
#include "missionlog/mission_files.h"
#include "resource_paths.h"

namespace fs = std::filesystem;

namespace auv::cli {

std::string vehiclesDir() { return app::vehiclesDir(); }

namespace {
std::vector<fs::path> logPaths(const std::vector<std::string>& logs) {
  std::vector<fs::path> paths;
  for (const auto& l : logs)
    if (!l.empty()) paths.emplace_back(l);
  if (paths.empty()) throw InputError("log", "missing", "give --log FILE or --log FOLDER (repeatable)");
  return paths;
}
}  // namespace

MissionLog readLogArgument(const std::vector<std::string>& logs, const ReadOptions& options, ReadReport& report) {
  return readMission(logPaths(logs), options, report);
}

std::string logArgumentLabel(const std::vector<std::string>& logs) { return missionLabel(logPaths(logs)); }

void writeJson(const nlohmann::json& j, const std::string& path) {
  if (path == "-") {
    std::cout << j.dump(2) << "\n";
    return;
  }
  // Write beside the target and rename, so an interrupted run never leaves a
  // half-written report where another tool expects a whole one.
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("json", "cannot write '" + path + "'", "check the folder exists and is writable");
    out << j.dump(2) << "\n";
    if (!out.flush()) throw InputError("json", "write to '" + path + "' failed", "check free disk space");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw InputError("json", "cannot replace '" + path + "': " + ec.message(), "check permissions");
}

ReadOptions logReadOptions(const std::string& cacheDir) {
  ReadOptions o;
  o.slocum_cache_dir = cacheDir;
  return o;
}

}  // namespace auv::cli
