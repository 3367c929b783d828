#include "cli_context.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "common/input_error.h"

namespace fs = std::filesystem;

namespace auv::cli {

std::string resourceDir() {
  if (const char* env = std::getenv("AUVBALLAST_RESOURCES"); env && *env) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / "share" / "auvballast" / "resources";
    if (fs::exists(installed / "vehicles")) return installed.string();
  }
  return AUV_SOURCE_RESOURCE_DIR;
}

std::string vehiclesDir() { return resourceDir() + "/vehicles"; }

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

}  // namespace auv::cli
