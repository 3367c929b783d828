#include "weighing/roll_correction.h"

#include <algorithm>
#include <cmath>

namespace auv {
namespace {

// Moves up to `want` kg from `port` to `stbd` (negative: the other way),
// within what the giving side holds and the receiving side can take, in
// whole pieces.
double shiftAcross(SlocumBallast& b, const SlocumLayout& L, SlocumItem port, SlocumItem stbd, double want,
                   double res) {
  const double to_stbd_max = std::min(b.at(port), L.item(stbd).capacity_kg - b.at(stbd));
  const double to_port_max = std::min(b.at(stbd), L.item(port).capacity_kg - b.at(port));
  double t = std::round(want / res) * res;
  t = std::clamp(t, -std::max(0.0, to_port_max), std::max(0.0, to_stbd_max));
  b.at(port) -= t;
  b.at(stbd) += t;
  return t;
}

double spanY(const SlocumLayout& L, SlocumItem port, SlocumItem stbd) {
  return L.item(stbd).position_m.y() - L.item(port).position_m.y();
}

}  // namespace

const char* rollMethodName(RollMethod m) {
  switch (m) {
    case RollMethod::BatteryOnly: return "battery";
    case RollMethod::WingRails: return "battery_and_wing_rails";
    case RollMethod::BowBottles: return "battery_and_bow_bottles";
    case RollMethod::RailsAndBottles: return "battery_wing_rails_and_bow_bottles";
  }
  return "?";
}

RollCorrection correctRoll(const SlocumLayout& L, const SlocumBallast& now, double mb, double M,
                           const Eigen::Vector2d& cg_yz_m) {
  const double res = L.mass_resolution_kg;
  const double arm = mb * L.battery.radius_m;
  const Eigen::Vector2d moment_now = M * cg_yz_m;
  const Eigen::Vector2d fixed = moment_now - movableMomentYZ(L, now, mb);
  // Lateral moment (component 0 of the (y, z) pair) of everything except
  // the battery: what the battery and the lateral shifts have to cancel.
  const double rest_y = moment_now[0] - arm * std::sin(now.battery_angle_rad);

  RollCorrection rc;
  for (int k = 0; k < 4; ++k) {
    RollOption o;
    o.method = static_cast<RollMethod>(k);
    o.after = now;
    double y = rest_y;
    if (o.method == RollMethod::WingRails || o.method == RollMethod::RailsAndBottles) {
      const double span = spanY(L, kRailPort, kRailStarboard);
      o.rail_shift_kg = shiftAcross(o.after, L, kRailPort, kRailStarboard, -y / span, res);
      y += o.rail_shift_kg * span;
    }
    if (o.method == RollMethod::BowBottles || o.method == RollMethod::RailsAndBottles) {
      const double span = spanY(L, kForePort, kForeStarboard);
      o.bottle_shift_kg = shiftAcross(o.after, L, kForePort, kForeStarboard, -y / span, res);
      y += o.bottle_shift_kg * span;
    }
    // Battery centre at r (sin phi, cos phi): y + arm sin(phi) = 0.
    const double s = -y / arm;
    const double s_max = std::sin(L.battery.max_angle_rad);
    o.feasible = std::abs(s) <= s_max;
    o.battery_angle_rad = std::asin(std::clamp(s, -s_max, s_max));
    o.after.battery_angle_rad = o.battery_angle_rad;
    o.cg_yz_m = (fixed + movableMomentYZ(L, o.after, mb)) / M;
    rc.options[static_cast<std::size_t>(k)] = o;
    if (o.feasible && rc.chosen < 0) rc.chosen = k;
  }
  return rc;
}

}  // namespace auv
