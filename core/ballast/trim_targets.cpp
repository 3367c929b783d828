#include "ballast/trim_targets.h"

#include <algorithm>
#include <cmath>

#include "common/units.h"

namespace auv::ballast {
namespace {

// Half-way for an angle band is taken on tan(angle), i.e. on the horizontal
// CG-CB offset that the pieces actually move, not on the angle itself.
void halfWayAngle(double now, double tol, double& lo, double& hi, double& centre) {
  if (!(std::abs(now) < units::degToRad(89.0))) return;  // capsized or vertical: no half-way
  const double t_now = std::tan(now), t_tol = std::tan(tol);
  const double shift = 0.5 * (t_now - std::clamp(t_now, -t_tol, t_tol));
  lo = std::atan(-t_tol + shift);
  hi = std::atan(t_tol + shift);
  centre = std::atan(shift);
}

}  // namespace

TrimTargets exactTargets(const TrimSpec& spec) {
  TrimTargets t;
  t.net_lo_kg = std::max(0.0, spec.net_buoyancy_min_kg);
  t.net_hi_kg = spec.net_buoyancy_max_kg;
  t.pitch_scale = units::degToRad(spec.pitch_tolerance_deg);
  t.roll_scale = units::degToRad(spec.roll_tolerance_deg);
  t.pitch_lo = -t.pitch_scale;
  t.pitch_hi = t.pitch_scale;
  t.roll_lo = -t.roll_scale;
  t.roll_hi = t.roll_scale;
  return t;
}

TrimTargets halfWayTargets(const TrimSpec& spec, double net_now_kg, double pitch_now_rad, double roll_now_rad) {
  TrimTargets t = exactTargets(spec);
  // Too light: move the band half-way. Too heavy: no half measures, the
  // vehicle must not stay negative, so the full band applies.
  const double shift = net_now_kg - std::clamp(net_now_kg, t.net_lo_kg, t.net_hi_kg);
  if (shift > 0.0) {
    t.net_lo_kg += 0.5 * shift;
    t.net_hi_kg += 0.5 * shift;
  }
  halfWayAngle(pitch_now_rad, t.pitch_scale, t.pitch_lo, t.pitch_hi, t.pitch_centre);
  halfWayAngle(roll_now_rad, t.roll_scale, t.roll_lo, t.roll_hi, t.roll_centre);
  return t;
}

}  // namespace auv::ballast
