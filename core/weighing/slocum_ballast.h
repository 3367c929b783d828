#pragma once
// What is installed in a Slocum glider's movable-mass places right now: the
// bottle and rail contents, the six disk-weight seats and the roll-battery
// angle. Every correction step takes one of these and returns the next.
#include <Eigen/Core>
#include <array>
#include <string>

#include "weighing/slocum_layout.h"

namespace auv {

struct DiskSeats {
  double top_kg = 0.0;
  double bottom_kg = 0.0;
};

struct SlocumBallast {
  std::array<double, kSlocumItemCount> item_kg{};  // indexed by SlocumItem
  std::array<DiskSeats, 3> disks{};                // columns A, B, C
  // Battery centre at (y, z) = r (sin phi, cos phi): positive = swung to
  // starboard, which rolls the glider starboard-down (m_roll > 0).
  double battery_angle_rad = 0.0;

  double& at(SlocumItem i) { return item_kg[static_cast<std::size_t>(i)]; }
  double at(SlocumItem i) const { return item_kg[static_cast<std::size_t>(i)]; }
};

// Sum of m * (y, z) over the bottles, rails, disks and battery: the part of
// the cross-section mass moment that ballasting can change.
Eigen::Vector2d movableMomentYZ(const SlocumLayout& layout, const SlocumBallast& b, double battery_mass_kg);

// Throws InputError naming "<prefix>.<item>" (e.g. "ballast_g.aft_upper",
// "ballast_g.disk_A_top") if a mass is negative, above its capacity or not
// finite, and `battery_field` if the battery is outside its travel.
void validateBallast(const SlocumLayout& layout, const SlocumBallast& b, const std::string& prefix,
                     const std::string& battery_field);

}  // namespace auv
