#include "ballast/trim_model.h"

#include <cmath>

namespace auv::ballast {

TrimOutcome outcomeFromD(double net_kg, const Eigen::Vector3d& d) {
  // Same formulas as staticTrimFromOffset, inlined: this runs at every leaf.
  TrimOutcome o;
  o.net_kg = net_kg;
  o.pitch_rad = std::atan2(-d.x(), std::hypot(d.y(), d.z()));
  o.roll_rad = std::atan2(d.y(), d.z());
  o.pitch_x_rad = std::atan2(-d.x(), d.z());
  o.stable = d.z() > 0.0;
  return o;
}

TrimOutcome TrimModel::outcome(double added_kg, const Eigen::Vector3d& added_moment_kgm) const {
  return outcomeFromD(displaced_kg - mass_kg - added_kg, d0 + added_moment_kgm);
}

TrimScores scoreOutcome(const TrimOutcome& o, const TrimTargets& t) {
  TrimScores s;
  s.pitch_violation = bandViolation(o.pitch_x_rad, t.pitch_lo, t.pitch_hi);
  s.roll_violation = bandViolation(o.roll_rad, t.roll_lo, t.roll_hi);
  const double p = (o.pitch_x_rad - t.pitch_centre) / t.pitch_scale;
  const double r = (o.roll_rad - t.roll_centre) / t.roll_scale;
  s.residual = p * p + r * r;
  return s;
}

}  // namespace auv::ballast
