#pragma once
// What every subcommand needs from the program around it: where the bundled
// resources are and how to write results. Keeps the command files free of
// environment lookups.
#include <nlohmann/json.hpp>
#include <string>

namespace auv::cli {

std::string vehiclesDir();  // see app/common/resource_paths.h

// Writes pretty JSON to `path` ("-" = stdout). Throws InputError if it cannot.
void writeJson(const nlohmann::json& j, const std::string& path);

}  // namespace auv::cli
