#include "weighing/roll_test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/input_error.h"
#include "weighing/weighing_messages.h"

namespace auv {
namespace {

constexpr double kMinRotationRad = 0.002;  // ~0.1 deg: below this the sensor noise dominates

std::string field(std::size_t i, const char* name) {
  return "roll_test.applied[" + std::to_string(i) + "]." + name;
}

}  // namespace

RollTestResult analyseRollTest(const RollTest& t, double M) {
  if (!std::isfinite(M) || M <= 0.0) {
    throw InputError("dry_mass_kg", "glider mass must be positive", "give the dry mass in kg");
  }
  if (!std::isfinite(t.initial_roll_rad) || std::abs(t.initial_roll_rad) > 1.0) {
    throw InputError("roll_test.initial_roll_rad", "must be a roll angle within +-1 rad",
                     "give the m_roll reading in radians with nothing hung");
  }
  if (t.applied.empty()) {
    throw InputError("roll_test.applied", "no applied masses", "hang at least one known mass and record the roll");
  }
  RollTestResult r;
  r.initial_roll_rad = t.initial_roll_rad;
  const double beta = t.initial_roll_rad;
  for (std::size_t i = 0; i < t.applied.size(); ++i) {
    const AppliedRollMass& a = t.applied[i];
    if (!std::isfinite(a.mass_kg) || a.mass_kg <= 0.0) {
      throw InputError(field(i, "mass_kg"), "must be a positive mass", "give the submerged mass in kg");
    }
    if (!std::isfinite(a.roll_rad) || std::abs(a.roll_rad) > 1.5) {
      throw InputError(field(i, "roll_rad"), "must be a roll angle within +-1.5 rad", "give the m_roll reading in radians");
    }
    const double turn = a.roll_rad - beta;
    if (std::abs(turn) < kMinRotationRad) {
      throw InputError(field(i, "roll_rad"), "the mass barely turned the glider (less than 0.002 rad)",
                       "hang a larger mass, or check that the reading was taken with it hanging");
    }
    const double moment = a.mass_kg * (a.y_m * std::cos(a.roll_rad) - a.z_m * std::sin(a.roll_rad));
    const double h = moment / (M * std::sin(turn));
    if (!(h > 0.0)) {
      throw InputError(field(i, "roll_rad"),
                       "the glider turned away from the side the mass hangs on (G would be above B)",
                       "roll is starboard-down positive (m_roll); a mass on the port rail makes it smaller");
    }
    r.h_each_m.push_back(h);
  }
  double sum = 0.0;
  for (double h : r.h_each_m) sum += h;
  r.h_m = sum / static_cast<double>(r.h_each_m.size());
  const auto [lo, hi] = std::minmax_element(r.h_each_m.begin(), r.h_each_m.end());
  r.spread_m = *hi - *lo;
  r.cg_yz_m = r.h_m * Eigen::Vector2d(std::sin(beta), std::cos(beta));
  if (r.h_m > 0.05) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f mm", r.h_m * 1000.0);
    r.warnings.push_back(Message(weighing::msg::kRollTestHLarge, {buf}));
  }
  if (r.h_each_m.size() > 1 && r.spread_m > 0.2 * r.h_m) {
    char spread[32], share[32];
    std::snprintf(spread, sizeof spread, "%.2f mm", r.spread_m * 1000.0);
    std::snprintf(share, sizeof share, "%.0f %%", 100.0 * r.spread_m / r.h_m);
    r.warnings.push_back(Message(weighing::msg::kRollTestSpread, {spread, share}));
  }
  return r;
}

}  // namespace auv
