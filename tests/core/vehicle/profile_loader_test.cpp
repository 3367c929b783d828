#include "vehicle/profile_loader.h"

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "vehicle/vehicle_catalog.h"

namespace auv {
namespace {

const std::string kVehicles = std::string(AUV_RESOURCE_DIR) + "/vehicles";

std::string errorOf(const std::string& json) {
  try {
    parseVehicleProfile(json, "bad.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kMinimal = R"({"id":"t","kind":"auv","mass_in_air_kg":10,
  "hull":{"length_m":1,"diameter_m":0.1,"volume_m3":0.01},"cb_mm":{"x_mm":0,"y_mm":0}})";

}  // namespace

TEST(VehicleProfile, Hugin1000MatchesThesisTables) {
  const VehicleProfile v = VehicleCatalog(kVehicles).load("hugin1000");
  EXPECT_EQ(v.kind, "auv");
  EXPECT_DOUBLE_EQ(v.mass_kg, 1498.0);
  // Thesis App. A: V = (1498 - (-65)) / 1024.8 = 1.5252 m^3.
  EXPECT_NEAR(v.hull.volume_m3, 1.5252, 5e-5);
  EXPECT_DOUBLE_EQ(v.hull.length_m, 5.23);
  EXPECT_NEAR(v.cb_m.x(), -0.1578, 1e-12);
  EXPECT_NEAR(v.cb_m.z(), -0.01138, 1e-12);
  ASSERT_EQ(v.points.size(), 4u);
  EXPECT_EQ(v.points[0].name, "fore_starboard");
  EXPECT_NEAR(v.points[0].position_m.x(), 1.0325, 1e-12);
  EXPECT_NEAR(v.points[3].position_m.y(), -0.325, 1e-12);
  EXPECT_EQ(v.kit.pieces_kg, (std::vector<double>{1.2, 2.4, 4.8}));
  EXPECT_EQ(v.kit.optional_pieces_kg, (std::vector<double>{0.5}));
  EXPECT_TRUE(v.sections.contains("weighing"));
}

TEST(VehicleProfile, EveryShippedProfileLoads) {
  VehicleCatalog cat(kVehicles);
  ASSERT_FALSE(cat.ids().empty());
  for (const auto& id : cat.ids()) {
    SCOPED_TRACE(id);
    const VehicleProfile v = cat.load(id);
    EXPECT_EQ(v.id, id);
    EXPECT_GT(v.hull.volume_m3, 0.0);
    EXPECT_GT(v.mass_kg, 0.0);
  }
}

TEST(VehicleProfile, HullVolumeFollowsTemperatureAndPressure) {
  HullModel h;
  h.volume_m3 = 0.05;
  h.reference_temperature_degC = 20;
  h.thermal_expansion_per_degC = 7e-5;
  h.compressibility_per_dbar = 4e-6;
  EXPECT_DOUBLE_EQ(h.volumeAt(20, 0), 0.05);
  EXPECT_NEAR(h.volumeAt(10, 0), 0.05 * (1 - 7e-4), 1e-15);
  EXPECT_NEAR(h.volumeAt(20, 1000), 0.05 * (1 - 4e-3), 1e-15);
}

TEST(VehicleProfile, MinimalProfileParses) {
  const auto v = parseVehicleProfile(kMinimal, "m.json");
  EXPECT_DOUBLE_EQ(v.hull.volume_m3, 0.01);
  EXPECT_TRUE(v.points.empty());
  EXPECT_DOUBLE_EQ(v.spec.net_buoyancy_max_kg, 1.2);
}

TEST(VehicleProfile, ErrorsNameFileFieldAndFix) {
  EXPECT_EQ(errorOf(R"({"kind":"auv"})"), "bad.json: id: missing required field; add \"id\" to the file");
  EXPECT_NE(errorOf(R"({"id":"t","kind":"boat"})").find("kind: unknown vehicle kind 'boat'"), std::string::npos);
  const std::string neg = errorOf(R"({"id":"t","kind":"auv","mass_in_air_kg":-3})");
  EXPECT_NE(neg.find("mass_in_air_kg: value -3 is out of range"), std::string::npos) << neg;
  const std::string str = errorOf(R"({"id":"t","kind":"auv","mass_in_air_kg":"heavy"})");
  EXPECT_NE(str.find("mass_in_air_kg: expected a number"), std::string::npos) << str;
}

TEST(VehicleProfile, SyntaxErrorsCarryLineAndColumn) {
  const std::string e = errorOf("{\n  \"id\": \"t\",\n  \"kind\": auv\n}");
  EXPECT_EQ(e.rfind("bad.json:3:", 0), 0u) << e;
}

TEST(VehicleProfile, NestedFieldPathsAreReported) {
  std::string j = kMinimal;
  j.insert(j.size() - 1, R"(,"adjustment_points":[{"name":"a","x_mm":0,"y_mm":0,"capacity_kg":-1}])");
  const std::string e = errorOf(j);
  EXPECT_NE(e.find("adjustment_points[0].capacity_kg"), std::string::npos) << e;
}

TEST(VehicleCatalog, UnknownVehicleListsTheKnownOnes) {
  try {
    VehicleCatalog(kVehicles).load("hugin9000");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown vehicle 'hugin9000'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("hugin1000"), std::string::npos);
  }
}

}  // namespace auv
