#pragma once
// Applied-mass roll test (Baird 2007, §4.2): the wingless glider hangs in the
// tank from its nose hook and tail loop, free to turn about its hull axis,
// which the report takes as B. At rest G is straight below B and the roll
// sensor reads beta; a known submerged mass hung from the hull turns it to
// theta. Moments about the axis:
//     M h sin(theta - beta) = m (y cos(theta) - z sin(theta))
// with (y, z) where the mass hangs (body axes, y starboard, z down). Angles
// follow the Slocum m_roll convention: positive = starboard down (port wing
// up). G then sits at (y_G, z_G) = h (sin beta, cos beta) from the axis.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "common/message.h"

namespace auv {

struct AppliedRollMass {
  double mass_kg = 0.0;   // submerged (apparent) mass of the hung weight
  double y_m = 0.0;       // where it hangs: + starboard, - port (report: the hull radius)
  double z_m = 0.0;       // + below the axis
  double roll_rad = 0.0;  // roll sensor reading with it hanging
};

struct RollTest {
  double initial_roll_rad = 0.0;  // beta, nothing hung
  std::vector<AppliedRollMass> applied;
};

struct RollTestResult {
  std::vector<double> h_each_m;   // one h per applied mass
  double h_m = 0.0;               // their mean (as the report does)
  double spread_m = 0.0;          // max - min of h_each_m
  double initial_roll_rad = 0.0;
  Eigen::Vector2d cg_yz_m = Eigen::Vector2d::Zero();  // G relative to the hull axis
  std::vector<Message> warnings;  // weighing_messages.h ids
};

// Throws InputError naming "roll_test.applied[i].<field>" when a reading
// cannot come from the stated mass (no rotation, or rotation away from the
// side the mass hangs on, which is the usual sign mistake).
RollTestResult analyseRollTest(const RollTest& test, double glider_mass_kg);

}  // namespace auv
