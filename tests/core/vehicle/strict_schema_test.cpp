// Unknown keys in our JSON files are refused with the file, the JSON path and
// the nearest known key, because a misspelt optional key would otherwise
// silently take its default (issue 15: `bg_mmm` became BG 0, `instaled_kg`
// meant nothing installed). Numbers beyond double range are refused with
// their line and column instead of escaping as a library exception.
#include <gtest/gtest.h>

#include "common/input_error.h"
#include "vehicle/installed_check.h"
#include "vehicle/json_reader.h"
#include "vehicle/nearest_key.h"
#include "vehicle/profile_loader.h"

namespace auv {
namespace {

std::string errorOf(const std::string& json) {
  try {
    parseVehicleProfile(json, "bad.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string profileWith(const std::string& extra) {
  return R"({"id":"t","kind":"auv","mass_in_air_kg":10,"hull":{"length_m":1,"diameter_m":0.1,"volume_m3":0.01},
    "cb_mm":{"x_mm":0,"y_mm":0},"adjustment_points":[{"name":"a","x_mm":100,"y_mm":0,"capacity_kg":40}])" +
         extra + "}";
}

}  // namespace

TEST(StrictSchema, MisspeltOptionalKeyIsRefusedWithTheNearestKnownOne) {
  const std::string m = errorOf(profileWith(R"(,"bg_mmm":30)"));
  EXPECT_NE(m.find("bad.json: bg_mmm: unknown field"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean bg_mm?"), std::string::npos) << m;
  EXPECT_NE(m.find("docs/formats/vehicle-profile.md"), std::string::npos) << m;
  // Nested objects and array elements name their JSON path.
  const std::string n = errorOf(profileWith(R"(,"spec":{"roll_tolerence_deg":0.2})"));
  EXPECT_NE(n.find("spec.roll_tolerence_deg"), std::string::npos) << n;
  EXPECT_NE(n.find("did you mean roll_tolerance_deg?"), std::string::npos) << n;
  const std::string p = errorOf(R"({"id":"t","kind":"auv","mass_in_air_kg":10,"hull":{"length_m":1,"diameter_m":0.1,
    "volume_m3":0.01},"cb_mm":{"x_mm":0,"y_mm":0},"adjustment_points":[{"name":"a","x_mm":1,"y_mm":0,"capcity_kg":4}]})");
  EXPECT_NE(p.find("adjustment_points[0].capcity_kg"), std::string::npos) << p;
  EXPECT_NE(p.find("did you mean capacity_kg?"), std::string::npos) << p;
  // The valid file is accepted (the check is not simply "refuse everything").
  EXPECT_EQ(errorOf(profileWith(R"(,"bg_mm":30)")), "no error");
}

TEST(StrictSchema, NearestKeyIsOnlyOfferedForPlausibleTypos) {
  EXPECT_EQ(keyDistance("instaled_kg", "installed_kg"), 1u);
  EXPECT_EQ(keyDistance("totl_kg", "total_kg"), 1u);
  EXPECT_EQ(keyDistance("bg_mn", "bg_mm"), 1u);
  EXPECT_EQ(keyDistance("ab", "ba"), 1u);  // a swap of neighbours is one edit
  EXPECT_EQ(nearestKey("instaled_kg", {"total_kg", "installed_kg", "rope_y_m"}), "installed_kg");
  EXPECT_EQ(nearestKey("totl_kg", {"total_kg", "installed_kg"}), "total_kg");
  EXPECT_EQ(nearestKey("weather", {"total_kg", "installed_kg"}), "");  // nothing close: no guess
}

TEST(StrictSchema, NumberBeyondDoubleRangeNamesFileLineAndColumn) {
  try {
    JsonReader::parseText("{\n  \"total_kg\": 1e999\n}\n", "crane.json");
    FAIL() << "1e999 must be refused";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.where().file, "crane.json");
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 15);
    EXPECT_NE(m.find("1e999"), std::string::npos) << m;
  }
}

TEST(StrictSchema, InstalledMassesAreCheckedAgainstEachPointsCapacity) {
  const VehicleProfile v = parseVehicleProfile(profileWith(""), "t.json");
  EXPECT_NO_THROW(checkInstalledKg(v, std::vector<double>{40.0}, "installed"));
  for (double bad : {40.1, 300000.0, 1e308, -0.1, std::nan("")}) {
    try {
      checkInstalledKg(v, std::vector<double>{bad}, "installed", {"w.json", 0, 0});
      FAIL() << bad << " kg must be refused";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "w.json");
      EXPECT_EQ(e.field(), "installed");
    }
  }
  EXPECT_THROW(checkInstalledKg(v, std::vector<double>{1.0, 2.0}, "installed"), InputError);
}

}  // namespace auv
