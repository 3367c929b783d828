#include "weighing/tank_weighing_file.h"

#include <algorithm>
#include <initializer_list>

#include "vehicle/json_reader.h"

namespace auv {
namespace {

constexpr double kGram = 1e-3;

// Grams in the file (the technician's scale), kg inside.
double grams(const JsonReader& r, const std::string& key, double hi) { return r.numberIn(key, 0.0, hi) * kGram; }
double grams(const JsonReader& r, const std::string& key, double hi, double fallback_g) {
  return r.numberIn(key, 0.0, hi, fallback_g) * kGram;
}

// Optional fields have defaults, so a typo ("lever_arm" for "lever_arm_m")
// would silently use the default: refuse names we do not know.
void rejectUnknown(const JsonReader& r, std::initializer_list<std::string_view> known) {
  r.refuseUnknownKeys(known, "docs/formats/slocum-tank-weighing.md");
}

SlocumBallast readBallast(const JsonReader& b) {
  rejectUnknown(b, {"fore_port", "fore_starboard", "aft_upper", "aft_lower", "wing_rail_port", "wing_rail_starboard",
                    "disk_A_top", "disk_B_top", "disk_C_top", "disk_A_bottom", "disk_B_bottom", "disk_C_bottom"});
  SlocumBallast s;
  for (int i = 0; i < kSlocumItemCount; ++i) {
    const auto item = static_cast<SlocumItem>(i);
    // Bottles are what the tank method changes: required. Rails may be empty.
    s.at(item) = item <= kAftLower ? grams(b, slocumItemName(item), 5000.0)
                                   : grams(b, slocumItemName(item), 5000.0, 0.0);
  }
  const char* columns[3] = {"A", "B", "C"};
  for (std::size_t k = 0; k < 3; ++k) {
    s.disks[k].top_kg = grams(b, std::string("disk_") + columns[k] + "_top", 5000.0, 0.0);
    s.disks[k].bottom_kg = grams(b, std::string("disk_") + columns[k] + "_bottom", 5000.0, 0.0);
  }
  return s;
}

TankWeighing fromJson(const nlohmann::json& doc, const std::string& file) {
  const JsonReader root(doc, file);
  rejectUnknown(root, {"method", "vehicle", "glider", "comment", "dry_mass_kg", "ballast_g", "roll_battery", "tank",
                       "target", "after_tank_step_g", "roll_test"});
  TankWeighing w;
  w.file = file;
  const std::string method = root.text("method", "tank");
  if (method != "tank") {
    root.fail("method", "this is a '" + method + "' weighing, not a Slocum tank weighing",
              "use \"method\": \"tank\" or the reader for that method");
  }
  w.vehicle = root.text("vehicle", "");
  w.glider = root.text("glider", "");
  w.readings.dry_mass_kg = root.numberIn("dry_mass_kg", 1.0, 1000.0);
  w.ballast = readBallast(root.child("ballast_g"));

  if (auto bat = root.optionalChild("roll_battery")) {
    rejectUnknown(*bat, {"mass_kg", "angle_rad"});
    if (bat->has("mass_kg")) w.battery_mass_kg = bat->numberIn("mass_kg", 0.1, 100.0);
    w.ballast.battery_angle_rad = bat->numberIn("angle_rad", -1.5, 1.5, 0.0);
  }

  const JsonReader tank = root.child("tank");
  rejectUnknown(tank, {"water", "density_kgm3", "temperature_degC", "bow_scale_g", "aft_scale_g"});
  const std::string water = tank.text("water", "fresh");
  if (water == "fresh") {
    w.readings.tank.density_kgm3 = tank.numberIn("density_kgm3", 990.0, 1010.0, kFreshTankDensityKgm3);
  } else if (water == "salt") {
    w.readings.tank.density_kgm3 = tank.numberIn("density_kgm3", 990.0, 1050.0);
  } else {
    tank.fail("water", "unknown tank water '" + water + "'", "use \"fresh\" or \"salt\" (salt needs density_kgm3)");
  }
  w.readings.tank.temperature_degC = tank.numberIn("temperature_degC", -2.0, 40.0);
  w.readings.bow_scale_kg = grams(tank, "bow_scale_g", 1e5);
  w.readings.aft_scale_kg = grams(tank, "aft_scale_g", 1e5);

  const JsonReader target = root.child("target");
  rejectUnknown(target, {"density_kgm3", "temperature_degC", "pressure_dbar", "salinity_psu"});
  w.readings.target.density_kgm3 = target.numberIn("density_kgm3", 990.0, 1060.0);
  w.readings.target.temperature_degC = target.numberIn("temperature_degC", -2.5, 40.0);
  w.readings.target_pressure_dbar = target.numberIn("pressure_dbar", 0.0, 2000.0, 0.0);
  w.target_salinity_psu = target.numberIn("salinity_psu", 0.0, 42.0, 0.0);

  if (auto after = root.optionalChild("after_tank_step_g")) {
    rejectUnknown(*after, {"fore_port", "fore_starboard", "aft_upper", "aft_lower"});
    std::array<double, 4> b{};
    for (int i = 0; i <= kAftLower; ++i) {
      b[static_cast<std::size_t>(i)] = grams(*after, slocumItemName(static_cast<SlocumItem>(i)), 5000.0);
    }
    w.bottles_after_tank_step_kg = b;
  }

  if (auto roll = root.optionalChild("roll_test")) {
    rejectUnknown(*roll, {"initial_roll_rad", "lever_arm_m", "applied"});
    RollTestRecord t;
    t.initial_roll_rad = roll->numberIn("initial_roll_rad", -1.0, 1.0);
    if (roll->has("lever_arm_m")) t.lever_arm_m = roll->numberIn("lever_arm_m", 0.01, 1.0);
    for (const JsonReader& a : roll->array("applied")) {
      rejectUnknown(a, {"mass_kg", "rail", "roll_rad"});
      RollTestRecord::Hang h;
      h.mass_kg = a.numberIn("mass_kg", 1e-3, 20.0);
      const std::string rail = a.text("rail");
      if (rail != "port" && rail != "starboard") {
        a.fail("rail", "unknown rail '" + rail + "'", "use \"port\" or \"starboard\"");
      }
      h.starboard = rail == "starboard";
      h.roll_rad = a.numberIn("roll_rad", -1.5, 1.5);
      t.applied.push_back(h);
    }
    if (t.applied.empty()) {
      roll->fail("applied", "no applied masses", "record at least one {mass_kg, rail, roll_rad}");
    }
    w.roll_test = t;
  }
  return w;
}

}  // namespace

TankWeighing parseTankWeighing(const std::string& json_text, const std::string& file) {
  return fromJson(JsonReader::parseText(json_text, file), file);
}

TankWeighing loadTankWeighing(const std::string& file) { return fromJson(JsonReader::parseFile(file), file); }

}  // namespace auv
