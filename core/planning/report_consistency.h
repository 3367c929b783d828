#pragma once
// An analysis report given to `plan` (or the wizard's pre-mission page) must
// belong to the vehicle being planned: another vehicle's net buoyancy and CG
// offset would give a plausible-looking but meaningless move. The report file
// is also read strictly, so a hand-edited typo ("net_bouyancy_kg") is refused
// rather than silently planning without that field.
#include <nlohmann/json.hpp>
#include <string>

#include "vehicle/vehicle_profile.h"

namespace auv {

// Throws InputError naming `report_name` when the report's vehicle id, kind or
// recommended points differ from `v`. Fields absent from the report (older
// reports, ballasting-file imports) are not checked.
void checkReportMatchesVehicle(const nlohmann::json& report, const std::string& report_name, const VehicleProfile& v);

// Refuses unknown keys in an analysis (or model-check) report file, with the
// nearest known key.
void refuseUnknownReportKeys(const nlohmann::json& report, const std::string& report_name);

}  // namespace auv
