#include "hydrostatics/static_trim.h"

#include <cmath>

namespace auv {

StaticTrim staticTrimFromOffset(const Eigen::Vector3d& d) {
  StaticTrim t;
  t.stable = d.z() > 0.0;
  t.pitch_rad = std::atan2(-d.x(), std::hypot(d.y(), d.z()));
  t.roll_rad = std::atan2(d.y(), d.z());
  return t;
}

StaticTrim staticTrim(double W, double B, const Eigen::Vector3d& rg, const Eigen::Vector3d& rb) {
  return staticTrimFromOffset(W * rg - B * rb);
}

}  // namespace auv
