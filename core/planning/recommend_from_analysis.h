#pragma once
// The post-mission report's `recommendation`: the pre-mission plan for flying
// the next mission in the same water as the analysed one, so the technician
// sees "what to change" right after "what went wrong". A separate
// `auvballast plan` handles other water and policies.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vehicle/vehicle_profile.h"

namespace auv {

// `analysis_json` is the analysis report (issue #3 contract). Returns
// {points, predicted, ...} or null with the reason in `why_not` when the log
// did not identify net buoyancy or the vehicle has no adjustment points.
// Gliders get planning/glider_ballast_plan.h's answer for the report's target.
nlohmann::json recommendFromAnalysis(const VehicleProfile& vehicle, const nlohmann::json& analysis_json,
                                     const std::vector<double>& installed_kg, std::string& why_not);

}  // namespace auv
