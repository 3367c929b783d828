#pragma once
// Static roll correction (Baird 2007, §4.2): bring G straight below B with
// the roll battery; if its travel is not enough, first move weight across the
// wing rails, then across the bow bottles, then both, and let the battery
// take up the rest. The first option that works is the one recommended, as
// in the report. A lateral move only goes as far as is useful (the point
// where the battery could return to centre), never past it.
#include <Eigen/Core>
#include <array>

#include "weighing/slocum_ballast.h"
#include "weighing/slocum_layout.h"

namespace auv {

enum class RollMethod { BatteryOnly = 0, WingRails = 1, BowBottles = 2, RailsAndBottles = 3 };

const char* rollMethodName(RollMethod m);

struct RollOption {
  RollMethod method = RollMethod::BatteryOnly;
  bool feasible = false;            // the battery angle is within its travel
  double battery_angle_rad = 0.0;   // required angle; clamped to the travel when not feasible
  double rail_shift_kg = 0.0;       // moved from the port to the starboard rail (negative: to port)
  double bottle_shift_kg = 0.0;     // moved from the port to the starboard bow bottle
  SlocumBallast after;
  Eigen::Vector2d cg_yz_m = Eigen::Vector2d::Zero();  // G after the move (y = 0 when feasible)
};

struct RollCorrection {
  std::array<RollOption, 4> options;  // in RollMethod order
  int chosen = -1;                    // first feasible option; -1 = none (options[3] is the best effort)

  const RollOption& best() const { return options[static_cast<std::size_t>(chosen >= 0 ? chosen : 3)]; }
};

// `cg_yz_m`: G of the whole glider (mass `glider_mass_kg`) relative to the
// hull axis with the ballast `now`, e.g. from analyseRollTest.
RollCorrection correctRoll(const SlocumLayout& layout, const SlocumBallast& now, double battery_mass_kg,
                           double glider_mass_kg, const Eigen::Vector2d& cg_yz_m);

}  // namespace auv
