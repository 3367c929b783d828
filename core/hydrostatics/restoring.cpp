#include "hydrostatics/restoring.h"

#include <cmath>
#include <numbers>

#include "common/input_error.h"

namespace auv {

Vector6d restoringForces(double W, double B, const Eigen::Vector3d& rg, const Eigen::Vector3d& rb,
                         double phi, double theta) {
  const double sphi = std::sin(phi), cphi = std::cos(phi);
  const double sth = std::sin(theta), cth = std::cos(theta);
  const Eigen::Vector3d m = W * rg - B * rb;  // (x_g W - x_b B, ...)
  Vector6d g;
  g << (W - B) * sth,
      -(W - B) * cth * sphi,
      -(W - B) * cth * cphi,
      -m.y() * cth * cphi + m.z() * cth * sphi,
      m.z() * sth + m.x() * cth * cphi,
      -m.x() * cth * sphi - m.y() * sth;
  return g;
}

double restoringPeriod(double inertia_total_kgm2, double weight_n, double bg_m) {
  if (!(bg_m > 0.0) || !(weight_n > 0.0)) {
    throw InputError("bg", "no restoring moment (CG not below CB)", "check the CG height");
  }
  return 2.0 * std::numbers::pi * std::sqrt(inertia_total_kgm2 / (weight_n * bg_m));
}

}  // namespace auv
