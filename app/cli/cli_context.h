#pragma once
// What every subcommand needs from the program around it: where the bundled
// resources are and how to write results. Keeps the command files free of
// environment lookups.
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "common/input_error.h"

namespace auv::cli {

std::string vehiclesDir();  // see app/common/resource_paths.h

// Writes pretty JSON to `path` ("-" = stdout). Throws InputError if it cannot.
void writeJson(const nlohmann::json& j, const std::string& path);

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
