#pragma once
// Where the movable masses of a Slocum glider sit and how much they hold
// (Baird 2007, NRC SR-2007-19), read from the "slocum" section of a vehicle
// profile. Cross-section coordinates are body axes (y starboard, z down)
// measured from the hull axis, which the report takes as B.
#include <Eigen/Core>
#include <array>
#include <string>

#include "vehicle/vehicle_profile.h"

namespace auv {

// The six places that hold lead shot / brass and can be filled or emptied.
enum SlocumItem {
  kForePort = 0,
  kForeStarboard,
  kAftUpper,
  kAftLower,
  kRailPort,
  kRailStarboard,
  kSlocumItemCount
};

// Stable ids, equal to the profile's adjustment point names.
const char* slocumItemName(SlocumItem item);

struct SlocumMassPoint {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double capacity_kg = 0.0;
};

// A disk-weight column: one seat above the axis, one below, same x. A disk
// may only swap between its two seats (report §4.3), so pitch is untouched.
struct DiskColumn {
  std::string name;  // "A", "B", "C"
  double x_m = 0.0;
  double top_z_m = -0.07;
  double bottom_z_m = 0.07;
};

struct RollBattery {
  double mass_kg = 7.86;
  double radius_m = 0.0635;       // centre of mass orbits the hull axis at this radius
  double max_angle_rad = 0.288;   // travel either side of bottom dead centre
};

struct SlocumLayout {
  double hull_radius_m = 0.1065;
  double target_h_arm_m = 0.006;
  double mass_resolution_kg = 0.001;  // smallest kit piece (lead shot, 1 g)
  RollBattery battery;
  std::array<SlocumMassPoint, kSlocumItemCount> items;
  std::array<DiskColumn, 3> disks;

  const SlocumMassPoint& item(SlocumItem i) const { return items[static_cast<std::size_t>(i)]; }
};

// Parses and validates vehicle.sections["slocum"]; InputError names the
// profile file and the field (e.g. "slocum.roll_battery.radius_m"). The
// bottles and rails must also be adjustment points of the same name with the
// same position and capacity, so recommendations can use the shared names.
SlocumLayout slocumLayout(const VehicleProfile& vehicle);

}  // namespace auv
