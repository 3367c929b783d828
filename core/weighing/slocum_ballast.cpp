#include "weighing/slocum_ballast.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/input_error.h"

namespace auv {
namespace {

std::string grams(double kg) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f g", kg * 1000.0);
  return buf;
}

}  // namespace

Eigen::Vector2d movableMomentYZ(const SlocumLayout& L, const SlocumBallast& b, double battery_mass_kg) {
  Eigen::Vector2d m = Eigen::Vector2d::Zero();
  for (int i = 0; i < kSlocumItemCount; ++i) {
    const auto& p = L.items[static_cast<std::size_t>(i)].position_m;
    m += b.item_kg[static_cast<std::size_t>(i)] * Eigen::Vector2d(p.y(), p.z());
  }
  for (std::size_t k = 0; k < 3; ++k) {
    m[1] += b.disks[k].top_kg * L.disks[k].top_z_m + b.disks[k].bottom_kg * L.disks[k].bottom_z_m;
  }
  m += battery_mass_kg * L.battery.radius_m *
       Eigen::Vector2d(std::sin(b.battery_angle_rad), std::cos(b.battery_angle_rad));
  return m;
}

void validateBallast(const SlocumLayout& L, const SlocumBallast& b, const std::string& prefix,
                     const std::string& battery_field) {
  for (int i = 0; i < kSlocumItemCount; ++i) {
    const auto item = static_cast<SlocumItem>(i);
    const double m = b.at(item);
    const std::string field = prefix + "." + slocumItemName(item);
    if (!std::isfinite(m) || m < 0.0) {
      throw InputError(field, "mass must be a number >= 0", "give the grams of lead/brass it holds");
    }
    // Half a gram of slack: the operator types whole grams.
    if (m > L.item(item).capacity_kg + 5e-4) {
      throw InputError(field, grams(m) + " is more than the " + grams(L.item(item).capacity_kg) + " it can hold",
                       "re-weigh the contents, or correct capacity_kg in the vehicle profile");
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string col = prefix + ".disk_" + L.disks[k].name;
    if (!std::isfinite(b.disks[k].top_kg) || b.disks[k].top_kg < 0.0) {
      throw InputError(col + "_top_g", "mass must be a number >= 0", "give the disk mass in grams (0 = empty seat)");
    }
    if (!std::isfinite(b.disks[k].bottom_kg) || b.disks[k].bottom_kg < 0.0) {
      throw InputError(col + "_bottom_g", "mass must be a number >= 0",
                       "give the disk mass in grams (0 = empty seat)");
    }
  }
  if (!std::isfinite(b.battery_angle_rad) || std::abs(b.battery_angle_rad) > L.battery.max_angle_rad + 1e-9) {
    throw InputError(battery_field, "outside the battery travel",
                     "give an angle within +-" + std::to_string(L.battery.max_angle_rad) + " rad");
  }
}

}  // namespace auv
