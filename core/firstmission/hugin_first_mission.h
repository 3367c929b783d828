#pragma once
// First-mission mode for a vehicle weighed with crane scales (HUGIN class,
// thesis §4.3): weighing -> weight, CG; planned water -> buoyancy; exact
// discrete solver -> which pieces go where; prediction after the move.
#include <vector>

#include "ballast/ballast_problem.h"
#include "firstmission/first_mission_report.h"
#include "firstmission/water_conditions.h"
#include "vehicle/vehicle_profile.h"
#include "weighing/crane_weighing.h"

namespace auv {

struct CraneFirstMissionInput {
  CraneWeighing weighing;               // cg_z_m is filled from the profile
  std::vector<double> installed_kg;     // adjustment mass now at each point (profile order); empty = none
  PlannedWater water;
  bool use_optional_pieces = false;     // e.g. HUGIN's 0.5 kg piece (thesis §8.1)
  BallastPolicy policy = BallastPolicy::Exact;
};

FirstMissionReport craneFirstMission(const VehicleProfile& vehicle, CraneFirstMissionInput input);

// Splits an installed mass at a point into kit pieces, largest first, so the
// solver knows what it may remove. Throws InputError if the mass is not a sum
// of kit pieces (to 1 g).
std::vector<int> decomposeInstalled(double mass_kg, const std::vector<double>& sizes_ascending,
                                    const std::string& point_name);

}  // namespace auv
