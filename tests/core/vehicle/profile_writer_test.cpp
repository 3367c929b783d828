// Profiles round-trip (issue 11 item 7): every shipped profile, loaded from the
// catalogue (companion sections merged), written by profileToJson and loaded
// again is the same vehicle, field for field and bit for bit, its
// vehicle-specific sections (the hydrodynamics included) equal; writing the
// reloaded vehicle gives the same JSON.
#include "vehicle/profile_writer.h"

#include <gtest/gtest.h>

#include "vehicle/profile_loader.h"
#include "vehicle/vehicle_catalog.h"

namespace auv {
namespace {

const std::string kVehicles = std::string(AUV_RESOURCE_DIR) + "/vehicles";

void expectSameVehicle(const VehicleProfile& a, const VehicleProfile& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.mass_kg, b.mass_kg);
  EXPECT_EQ(a.hull.volume_m3, b.hull.volume_m3);
  EXPECT_EQ(a.hull.reference_temperature_degC, b.hull.reference_temperature_degC);
  EXPECT_EQ(a.hull.thermal_expansion_per_degC, b.hull.thermal_expansion_per_degC);
  EXPECT_EQ(a.hull.compressibility_per_dbar, b.hull.compressibility_per_dbar);
  EXPECT_EQ(a.hull.length_m, b.hull.length_m);
  EXPECT_EQ(a.hull.diameter_m, b.hull.diameter_m);
  EXPECT_EQ(a.cb_m, b.cb_m);
  ASSERT_EQ(a.cg_m.has_value(), b.cg_m.has_value());
  if (a.cg_m) {
    EXPECT_EQ(*a.cg_m, *b.cg_m);
  }
  EXPECT_EQ(a.bg_m, b.bg_m);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].name, b.points[i].name);
    EXPECT_EQ(a.points[i].label, b.points[i].label);
    EXPECT_EQ(a.points[i].position_m, b.points[i].position_m) << a.points[i].name;
    EXPECT_EQ(a.points[i].capacity_kg, b.points[i].capacity_kg);
  }
  EXPECT_EQ(a.kit.pieces_kg, b.kit.pieces_kg);
  EXPECT_EQ(a.kit.optional_pieces_kg, b.kit.optional_pieces_kg);
  EXPECT_EQ(a.spec.net_buoyancy_min_kg, b.spec.net_buoyancy_min_kg);
  EXPECT_EQ(a.spec.net_buoyancy_max_kg, b.spec.net_buoyancy_max_kg);
  EXPECT_EQ(a.spec.pitch_tolerance_deg, b.spec.pitch_tolerance_deg);
  EXPECT_EQ(a.spec.roll_tolerance_deg, b.spec.roll_tolerance_deg);
  EXPECT_EQ(a.sections, b.sections);
}

TEST(ProfileWriter, EveryShippedProfileRoundTrips) {
  const VehicleCatalog catalog(kVehicles);
  ASSERT_GE(catalog.ids().size(), 3u);
  for (const std::string& id : catalog.ids()) {
    SCOPED_TRACE(id);
    const VehicleProfile v = catalog.load(id);
    const nlohmann::json j = profileToJson(v);
    const VehicleProfile again = parseVehicleProfile(j.dump(2), "/tmp/elsewhere/" + id + ".copy.json");
    expectSameVehicle(v, again);
    EXPECT_EQ(profileToJson(again), j);
    // Read from a path, as `--vehicle P` does: no companion lookup needed.
    if (v.kind == "auv") {
      EXPECT_TRUE(again.sections.contains("hydrodynamics"));
    }
  }
}

TEST(ProfileWriter, HuginCarriesItsCompanionHydrodynamics) {
  // HUGIN's hydrodynamics live in resources/sim/hugin1000_hydrodynamics.json;
  // a written HUGIN profile holds them itself.
  const VehicleProfile v = VehicleCatalog(kVehicles).load("hugin1000");
  ASSERT_FALSE(v.sections_file.empty());
  const nlohmann::json j = profileToJson(v);
  ASSERT_TRUE(j.contains("hydrodynamics"));
  EXPECT_EQ(j["hydrodynamics"]["Mw_prime"].get<double>(), -4.5e-3);  // the companion file's value
  EXPECT_TRUE(j.contains("autopilot"));
  EXPECT_TRUE(j.contains("weighing"));
}

}  // namespace
}  // namespace auv
