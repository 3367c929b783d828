#pragma once
// What the vehicle will do with the pieces the technician actually put in,
// which may differ from the plan (a piece short, one too many, another
// point). The same vehicle as the plan (its estimated mass and CG and the
// planned waters) with the masses `installed_after_kg` instead of the plan's
// move: net buoyancy at every planned point, the exact static attitude at the
// operating point, and the 1-sigma of each from the estimate, like the plan.
#include <optional>
#include <vector>

#include "planning/pre_mission_plan.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

struct InstalledPrediction {
  std::vector<double> add_kg;  // per point: installed after - before
  double net_buoyancy_kg = 0.0, pitch_deg = 0.0, roll_deg = 0.0;  // at the operating point
  double net_sigma_kg = 0.0, pitch_sigma_deg = 0.0, roll_sigma_deg = 0.0;
  std::vector<double> net_at_points_kg;  // plan.at_points order
  bool buoyancy_in_band = false, pitch_in_band = false, roll_in_band = false;
  bool safe = false;  // net >= the plan's margin at every planned point
  // Level flight at the plan's cruise speed (planning/flight_pitch.h); unset
  // when the plan has none.
  std::optional<double> flight_pitch_deg;
  std::optional<bool> flight_pitch_in_band;
};

// `installed_before_kg` is what the plan started from (PreMissionInput's
// installed_kg; empty = none). Throws InputError naming the point when a
// mass is negative, not finite or over the point's capacity.
InstalledPrediction predictInstalled(const VehicleProfile& v, const PreMissionPlan& plan,
                                     const std::vector<double>& installed_before_kg,
                                     const std::vector<double>& installed_after_kg);

}  // namespace auv
