#pragma once
// What every subcommand needs from the program around it: where the bundled
// resources are and how to write results. Keeps the command files free of
// environment lookups.
#include <nlohmann/json.hpp>
#include <string>

namespace auv::cli {

// Resource folder: $AUVBALLAST_RESOURCES, else <exe>/../share/auvballast/resources
// (installed), else the source tree's resources/ (build tree).
std::string resourceDir();
std::string vehiclesDir();

// Writes pretty JSON to `path` ("-" = stdout). Throws InputError if it cannot.
void writeJson(const nlohmann::json& j, const std::string& path);

}  // namespace auv::cli
