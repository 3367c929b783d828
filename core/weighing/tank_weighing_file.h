#pragma once
// A Slocum tank-weighing session saved as JSON
// (docs/formats/slocum-tank-weighing.md): what the report's MATLAB script
// asked for at its prompts, so the CLI, the GUI and the tests can replay it.
#include <string>

#include "weighing/tank_weighing.h"

namespace auv {

// Fresh tank water when the file says "water": "fresh" and gives no density
// (the report's tank_dens constant).
inline constexpr double kFreshTankDensityKgm3 = 1000.0;

// Throws InputError naming the file and the JSON path of a bad field
// ("session.json: tank.bow_scale_g: missing required field; ...").
TankWeighing loadTankWeighing(const std::string& file);
TankWeighing parseTankWeighing(const std::string& json_text, const std::string& file);

}  // namespace auv
