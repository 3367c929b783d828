#pragma once
// The glider target flags shared by analyze, model-check and plan:
// --target-density KG_M3, --target-pressure DBAR, --target-temperature DEGC,
// --target-depth M (the log's own CTD profile supplies T, S and p there).
#include <CLI/CLI.hpp>
#include <string>

#include "analysis/glider_target.h"

namespace auv::cli {

struct TargetFlags {
  std::string density, pressure, temperature, depth;
  void add(CLI::App* cmd);
  analysis::GliderTargetRequest request() const;  // throws InputError naming the flag
};

}  // namespace auv::cli
