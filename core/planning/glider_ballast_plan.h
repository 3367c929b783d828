#pragma once
// Where a glider's grams go, from an analysis or model-check report (the
// mass to add for the target water and the log's pitch and roll trim):
//  - Slocum: bow-bottle / aft-bottle grams from Baird 2007's level split
//    plus the pitch-moment the trim asks for (battery needed for level flight
//    at pump zero moved back to the profile's centre), through the tank
//    method's bottle step (capacities, 1 g pieces, never ending heavy); roll
//    at zero roll command to a port/starboard wing-rail transfer.
//  - Seaglider: the lead change and new $C_VBD / $C_PITCH as basestation's
//    ballast calculation does it (VBD cm3 per count, lead 11.296 g/cm3).
//  - SeaExplorer: the mass change and the linear-battery position for level
//    trim; what its log cannot tell is listed.
// The result is JSON: {vehicle_type, mass_to_add_g, target, points[], ...,
// cannot_tell[], warnings[]}.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/glider_target.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

struct GliderPlanInput {
  nlohmann::json report;                      // analysis or model-check JSON
  std::vector<double> installed_kg;           // per adjustment point, empty = unknown
  std::optional<analysis::GliderTarget> target;  // another water than the report's
};

// Throws InputError when the report has no glider mass to add.
nlohmann::json planGliderBallast(const VehicleProfile& vehicle, const GliderPlanInput& input);

// Mass to add (kg) at `target` from a report's fitted hull volume and the
// volume terms it used; nullopt when the report does not carry them.
std::optional<double> massToAddAtTargetKg(const nlohmann::json& report, const analysis::GliderTarget& target);

// A target for `plan`, which has no log: the report's target with the given
// values replacing its own; --target-depth sets the pressure (UNESCO, at
// `latitude_deg`); a changed p or T without a density recomputes it with
// EOS-80 from the report's salinity.
analysis::GliderTarget targetFromReport(const nlohmann::json& report, const analysis::GliderTargetRequest& request,
                                        double latitude_deg);

std::string gliderPlanText(const nlohmann::json& plan);

}  // namespace auv
