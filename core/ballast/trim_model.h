#pragma once
// The vehicle's static state as a function of the mass added at the points.
// Everything is carried in d = W r_G - B r_B (kg m, g cancels): the exact
// equilibrium attitude depends on d only (hydrostatics/static_trim.h), and
// d is linear in the added masses, which is what makes bounding cheap.
//
// The solver ranks pitch by the fore-aft alignment alone,
// pitch_x = atan2(-d_x, d_z), not by the exact pitch atan2(-d_x, |d_yz|):
// the exact pitch shrinks as the vehicle rolls, so ranking by it would buy
// a little pitch with a lot of roll (thesis case 2: 22 deg of roll for
// 0.1 deg of pitch). pitch_x equals the exact pitch at zero roll and is never
// smaller in magnitude, so "pitch_x in band" implies "pitch in band".
#include <Eigen/Core>

#include "ballast/trim_targets.h"

namespace auv::ballast {

struct TrimOutcome {
  double net_kg = 0;  // displaced - weight, positive = too light
  double pitch_rad = 0, roll_rad = 0;  // exact static attitude
  double pitch_x_rad = 0;              // fore-aft alignment, what pitch is ranked by
  bool stable = false;
};

struct TrimScores {
  double pitch_violation = 0;  // rad of pitch_x outside the pitch band
  double roll_violation = 0;   // rad outside the roll band
  double residual = 0;         // ((pitch_x - c)/tol)^2 + ((roll - c)/tol)^2
};

struct TrimModel {
  double mass_kg = 0;        // before the move
  double displaced_kg = 0;   // rho V
  Eigen::Vector3d d0 = Eigen::Vector3d::Zero();  // W r_G - B r_B before the move

  TrimOutcome outcome(double added_kg, const Eigen::Vector3d& added_moment_kgm) const;
};

TrimOutcome outcomeFromD(double net_kg, const Eigen::Vector3d& d);
TrimScores scoreOutcome(const TrimOutcome& o, const TrimTargets& t);

}  // namespace auv::ballast
