#pragma once
#include <string>

#include "vehicle/vehicle_profile.h"

namespace auv {

// Reads and validates a vehicle profile JSON file. Throws InputError naming the
// file and the field on any missing, mistyped or implausible value.
VehicleProfile loadVehicleProfile(const std::string& file);
VehicleProfile parseVehicleProfile(const std::string& json_text, const std::string& file);

}  // namespace auv
