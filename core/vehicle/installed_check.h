#pragma once
// Installed adjustment masses are typed by a person or read from a file, and
// the solvers allocate per kilogram of them: check them against the points
// before anything depends on them (300000 kg at a 40 kg point is a typo, not
// a ballast state).
#include <span>
#include <string>

#include "common/input_error.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

// Throws InputError(field, ..., where) unless there is one finite mass per
// adjustment point, each between 0 and the point's capacity_kg. Callers
// skip the check when no masses were given (an empty list means "none").
void checkInstalledKg(const VehicleProfile& v, std::span<const double> kg, const std::string& field,
                      const InputLocation& where = {});

}  // namespace auv
