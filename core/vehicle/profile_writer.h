#pragma once
// A vehicle profile as JSON, the inverse of profile_loader.h: what
// loadVehicleProfile reads back as the same vehicle, bit for bit, with every
// vehicle-specific section it carries (the hydrodynamics companion of a
// catalogue vehicle included, so that a written profile is a whole vehicle
// wherever it is read from).
#include <string>

#include <nlohmann/json.hpp>

#include "vehicle/vehicle_profile.h"

namespace auv {

nlohmann::json profileToJson(const VehicleProfile& v);

}  // namespace auv
