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
// `calibrated`: a "hydrodynamics" section calibrated from the log (TrimEstimate::
// calibrated_hydrodynamics), used instead of the profile's when given.
std::optional<double> flightPitchDeg(const VehicleProfile& v, double speed_mps, double mass_kg,
                                     const Eigen::Vector3d& cg_m, const PlannedPointResult& operating,
                                     const std::optional<nlohmann::json>& calibrated = std::nullopt);

// Plane lever l = M_e / Z_e [m] (calibrated or profile): flying level at zero
// pitch needs W x_G = l (B - W), at every speed. nullopt without planes.
std::optional<double> planeLeverM(const VehicleProfile& v, const std::optional<nlohmann::json>& calibrated);

}  // namespace auv
