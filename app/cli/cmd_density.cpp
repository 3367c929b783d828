#include <cstdio>
#include <memory>

#include "cli_context.h"
#include "commands.h"
#include "number_list.h"
#include "seawater/seawater.h"

namespace auv::cli {

Command addDensityCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("density", "In-situ seawater density (EOS-80 with pressure) in kg/m3");
  struct Opts {
    std::string salinity, temperature, pressure = "0", json;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--salinity", o->salinity, "Practical salinity, PSU")->required();
  cmd->add_option("--temperature", o->temperature, "In-situ temperature, degC (ITS-90)")->required();
  cmd->add_option("--pressure", o->pressure, "Sea pressure, dbar (0 at the surface)")->capture_default_str();
  cmd->add_option("--json", o->json, "Write {salinity_psu, temperature_degC, pressure_dbar, density_kgm3} here");
  return {cmd, [o]() {
            const double s = parseNumber(o->salinity, "salinity", "practical salinity in PSU, e.g. 35");
            const double t = parseNumber(o->temperature, "temperature", "temperature in degC, e.g. 4");
            const double p = parseNumber(o->pressure, "pressure", "sea pressure in dbar, e.g. 100");
            const double rho = seawater::density(s, t, p);
            if (!o->json.empty()) {
              writeJson({{"salinity_psu", s}, {"temperature_degC", t}, {"pressure_dbar", p}, {"density_kgm3", rho}},
                        o->json);
            }
            if (o->json != "-") std::printf("%.5f\n", rho);
            return 0;
          }};
}

}  // namespace auv::cli
