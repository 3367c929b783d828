#include "resource_paths.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace auv::app {

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
std::string examplesDir() { return resourceDir() + "/examples"; }

}  // namespace auv::app
