#include <cstdio>
#include <iostream>
#include <memory>

#include "cli_context.h"
#include "commands.h"
#include "vehicle/vehicle_catalog.h"

namespace auv::cli {

Command addVehiclesCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("vehicles", "List the bundled vehicle profiles");
  auto json = std::make_shared<std::string>();
  cmd->add_option("--json", *json, "Also write the list as JSON to this file ('-' = stdout)");
  return {cmd, [json]() {
    VehicleCatalog cat(vehiclesDir());
    nlohmann::json list = nlohmann::json::array();
    for (const auto& id : cat.ids()) {
      const VehicleProfile v = cat.load(id);
      if (json->empty()) {
        std::printf("%-12s %-7s %-22s %8.1f kg  %.4f m3  %zu adjustment points\n", v.id.c_str(), v.kind.c_str(),
                    v.name.c_str(), v.mass_kg, v.hull.volume_m3, v.points.size());
      }
      list.push_back({{"id", v.id}, {"name", v.name}, {"kind", v.kind}, {"mass_kg", v.mass_kg},
                      {"volume_m3", v.hull.volume_m3}, {"points", v.points.size()}});
    }
    if (!json->empty()) writeJson(list, *json);
    return 0;
  }};
}

}  // namespace auv::cli
