#include "weighing/slocum_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/input_error.h"
#include "common/units.h"
#include "vehicle/json_reader.h"

namespace auv {
namespace {

constexpr const char* kNames[kSlocumItemCount] = {"fore_port", "fore_starboard", "aft_upper",
                                                 "aft_lower", "wing_rail_port", "wing_rail_starboard"};

SlocumMassPoint readMassPoint(const JsonReader& r) {
  SlocumMassPoint p;
  p.position_m = {units::mmToM(r.numberIn("x_mm", -5000.0, 5000.0)),
                  units::mmToM(r.numberIn("y_mm", -500.0, 500.0)),
                  units::mmToM(r.numberIn("z_mm", -500.0, 500.0))};
  p.capacity_kg = r.numberIn("capacity_kg", 0.0, 50.0);
  return p;
}

// The same place described twice must agree, or one of them is a typo.
void crossCheck(const VehicleProfile& v, const JsonReader& parent, SlocumItem item, const SlocumMassPoint& p) {
  const std::string name = kNames[item];
  const AdjustmentPoint* ap = v.findPoint(name);
  if (!ap) {
    parent.fail(name, "has no adjustment point named '" + name + "'",
           "add \"" + name + "\" to adjustment_points with the same position and capacity");
  }
  if ((ap->position_m - p.position_m).norm() > 5e-5 || std::abs(ap->capacity_kg - p.capacity_kg) > 5e-4) {
    parent.fail(name, "disagrees with adjustment point '" + name + "' (position or capacity_kg)",
           "make adjustment_points and the slocum section give the same numbers");
  }
}

}  // namespace

const char* slocumItemName(SlocumItem item) { return kNames[item]; }

SlocumLayout slocumLayout(const VehicleProfile& v) {
  if (!v.sections.contains("slocum")) {
    throw InputError("slocum", "profile '" + v.id + "' has no \"slocum\" section",
                     "use a Slocum profile such as slocum_g2, or add the section", {v.file, 0, 0});
  }
  const JsonReader s(v.sections.at("slocum"), v.file, "slocum");
  SlocumLayout L;
  L.hull_radius_m = s.numberIn("hull_radius_m", 0.02, 1.0);
  L.target_h_arm_m = units::mmToM(s.numberIn("target_h_arm_mm", 0.1, 100.0));

  const JsonReader b = s.child("roll_battery");
  L.battery.mass_kg = b.numberIn("mass_kg", 0.1, 100.0);
  L.battery.radius_m = b.numberIn("radius_m", 0.001, 0.5);
  L.battery.max_angle_rad = b.numberIn("max_angle_rad", 0.0, 1.5);

  const JsonReader bottles = s.child("ballast_bottles");
  const JsonReader rails = s.child("wing_rails");
  for (int i = 0; i < kSlocumItemCount; ++i) {
    const auto item = static_cast<SlocumItem>(i);
    const JsonReader& parent = item <= kAftLower ? bottles : rails;
    L.items[static_cast<std::size_t>(i)] = readMassPoint(parent.child(kNames[i]));
    crossCheck(v, parent, item, L.items[static_cast<std::size_t>(i)]);
  }
  // The formulas move mass sideways between a port/starboard pair and
  // vertically between the aft pair; they assume that geometry.
  const auto& fp = L.item(kForePort).position_m;
  const auto& fs = L.item(kForeStarboard).position_m;
  if (!(fp.y() < 0.0 && fs.y() > 0.0) || std::abs(fp.z() - fs.z()) > 1e-4 || std::abs(fp.x() - fs.x()) > 1e-4) {
    bottles.fail("fore_port", "the bow bottles must be a port (y < 0) / starboard (y > 0) pair at one x and z",
                 "check the signs of y_mm and that x_mm, z_mm match");
  }
  const auto& au = L.item(kAftUpper).position_m;
  const auto& al = L.item(kAftLower).position_m;
  if (!(au.z() < al.z()) || std::abs(au.x() - al.x()) > 1e-4) {
    bottles.fail("aft_upper", "the aft bottles must be an upper (smaller z, z down) / lower pair at one x",
                 "check z_mm (z points down) and x_mm");
  }
  if (!(fp.x() > au.x())) {
    bottles.fail("fore_port", "the bow bottles must be forward of the aft bottles", "check x_mm (x forward)");
  }
  const auto& rp = L.item(kRailPort).position_m;
  const auto& rs = L.item(kRailStarboard).position_m;
  if (!(rp.y() < 0.0 && rs.y() > 0.0) || std::abs(rp.z() - rs.z()) > 1e-4 || std::abs(rp.x() - rs.x()) > 1e-4) {
    rails.fail("wing_rail_port", "the wing rails must be a port (y < 0) / starboard (y > 0) pair at one x and z",
               "check the signs of y_mm and that x_mm, z_mm match");
  }

  const JsonReader disks = s.child("disk_weights");
  const char* columns[3] = {"A", "B", "C"};
  for (std::size_t k = 0; k < 3; ++k) {
    const JsonReader d = disks.child(columns[k]);
    DiskColumn c;
    c.name = columns[k];
    c.x_m = units::mmToM(d.numberIn("x_mm", -5000.0, 5000.0));
    c.top_z_m = units::mmToM(d.numberIn("top_z_mm", -500.0, 500.0));
    c.bottom_z_m = units::mmToM(d.numberIn("bottom_z_mm", -500.0, 500.0));
    if (!(c.top_z_m < c.bottom_z_m)) {
      d.fail("top_z_mm", "the top seat must be above the bottom seat", "z points down: top_z_mm < bottom_z_mm");
    }
    L.disks[k] = c;
  }

  if (v.kit.pieces_kg.empty()) {
    throw InputError("weight_kit.pieces_kg", "the Slocum tank method needs the lead-shot resolution",
                     "give \"weight_kit\": {\"pieces_kg\": [0.001]}", {v.file, 0, 0});
  }
  L.mass_resolution_kg = v.kit.pieces_kg.front();
  return L;
}

}  // namespace auv
