#pragma once
// The pitch the vehicle will fly level at the last mission's cruise speed,
// for a mass and CG in the planned operating water: the spec's pitch band
// applies here (thesis §5.3.2; docs/decisions/planning-flight-attitude.md),
// not to the attitude at rest.
#include <optional>

#include <Eigen/Core>

#include "planning/pre_mission_plan.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

// nullopt when the profile has no hydrodynamics with planes, the speed is
// unknown (<= 0) or no level trim exists within +-30 deg.
std::optional<double> flightPitchDeg(const VehicleProfile& v, double speed_mps, double mass_kg,
                                     const Eigen::Vector3d& cg_m, const PlannedPointResult& operating);

}  // namespace auv
