#pragma once
// Static equilibrium attitude of a submerged vehicle: the net restoring moment
// (W r_g - B r_b) x n vanishes when the gravity direction n (body axes) is
// parallel to d = W r_g - B r_b. Exact, not small-angle:
//   pitch = atan2(-d_x, sqrt(d_y^2 + d_z^2)),  roll = atan2(d_y, d_z).
// With W = B this is the familiar tan(theta) = -(x_g - x_b)/(z_g - z_b).
#include <Eigen/Core>

namespace auv {

struct StaticTrim {
  double pitch_rad = 0.0;  // nose up positive
  double roll_rad = 0.0;   // starboard down positive
  bool stable = false;     // d_z > 0: the moment centre is below CB (upright is stable)
};

StaticTrim staticTrim(double weight_n, double buoyancy_n, const Eigen::Vector3d& r_g,
                      const Eigen::Vector3d& r_b);

// Neutral-buoyancy shorthand from the CG - CB offset alone.
StaticTrim staticTrimFromOffset(const Eigen::Vector3d& cg_minus_cb_m);

}  // namespace auv
