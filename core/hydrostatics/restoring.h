#pragma once
// Restoring forces and moments of a submerged body, Fossen (2011) eq. 4.6,
// in body axes (x fwd, y stbd, z down), Euler angles roll phi, pitch theta.
// The thesis's eq. 2.10 has sign and term errors in the pitch and yaw rows;
// see docs/decisions/restoring-forces.md.
#include <Eigen/Core>

namespace auv {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// g(eta) as it appears on the left side of M nu_dot + C nu + D nu + g = tau.
// W, B in newtons; r_g, r_b in metres.
Vector6d restoringForces(double weight_n, double buoyancy_n, const Eigen::Vector3d& r_g,
                         const Eigen::Vector3d& r_b, double roll_rad, double pitch_rad);

// Small-angle roll/pitch natural period of a submerged body:
// T = 2 pi sqrt(I_total / (W * BG)).
double restoringPeriod(double inertia_total_kgm2, double weight_n, double bg_m);

}  // namespace auv
