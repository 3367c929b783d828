#include "target_flags.h"

#include "number_list.h"

namespace auv::cli {

void TargetFlags::add(CLI::App* cmd) {
  cmd->add_option("--target-density", density,
                  "Gliders: density of the next deployment's water, kg/m3 (default: the log's own water at the bottom of its "
                  "deepest yo)");
  cmd->add_option("--target-pressure", pressure, "Gliders: pressure where the glider must be neutral, dbar (pump at zero)");
  cmd->add_option("--target-temperature", temperature, "Gliders: water temperature there, degC");
  cmd->add_option("--target-depth", depth,
                  "Gliders: neutral at this depth, m, with T, S and p from the log's own CTD profile there "
                  "(the --target-* values given override it)");
}

analysis::GliderTargetRequest TargetFlags::request() const {
  analysis::GliderTargetRequest q;
  if (!density.empty()) q.density_kgm3 = parseNumber(density, "target-density", "the target water density in kg/m3");
  if (!pressure.empty()) q.pressure_dbar = parseNumber(pressure, "target-pressure", "the target pressure in dbar");
  if (!temperature.empty())
    q.temperature_degC = parseNumber(temperature, "target-temperature", "the target water temperature in degC");
  if (!depth.empty()) q.depth_m = parseNumber(depth, "target-depth", "the target depth in m");
  return q;
}

}  // namespace auv::cli
