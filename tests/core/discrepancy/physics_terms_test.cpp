#include "discrepancy/physics_terms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "common/input_error.h"

namespace auv::discrepancy {
namespace {

TEST(PhysicsTerms, TheLibraryHasTheIssuesIdsAndUnits) {
  const std::pair<const char*, const char*> expected[] = {
      {"hull_compressibility", "1/dbar"}, {"thermal_expansion", "1/degC"},
      {"propeller_torque", "N*m/rpm^2"},   {"mass_drift", "kg/h"},
      {"pitch_sensor_bias", "deg"},        {"roll_sensor_bias", "deg"},
      {"depth_sensor_offset", "m"},        {"quadratic_pitch_damping", "scale of the calibrated coefficient"},
      {"vertical_current", "m/s"}};
  std::set<std::string> ids;
  for (const auto& [id, unit] : expected) {
    const auto k = findTerm(id);
    ASSERT_TRUE(k.has_value()) << id;
    const PhysicsTerm& t = termLibrary()[*k];
    EXPECT_EQ(t.unit, unit);
    EXPECT_LT(t.lower, 0.0);  // "no effect" is inside the plausible range
    EXPECT_GT(t.upper, 0.0);
    EXPECT_GT(t.typical, 0.0);
    EXPECT_LT(t.typical, t.upper);
    EXPECT_NE(t.families, 0u);
    ids.insert(std::string(t.id));
  }
  EXPECT_EQ(ids.size(), kTermCount);
  EXPECT_FALSE(findTerm("ballast").has_value());  // the ballast state is never a term
}

// Each term moves exactly one effect, linearly in its value (the equation
// error's regressors), and one simulator knob by the same amount.
TEST(PhysicsTerms, EachTermActsOnItsOwnEffectLinearly) {
  TermInputs in;
  in.hours_from_reference = 2.0;
  in.pressure_dbar = 300.0;
  in.temperature_degC = 12.0;
  in.reference_temperature_degC = 20.0;
  in.prop_torque_basis = 9e4;  // 300 rpm squared
  in.pitch_damping_basis = -0.8;
  for (std::size_t k = 0; k < kTermCount; ++k) {
    const PhysicsTerm& t = termLibrary()[k];
    TermValues v{};
    v[k] = t.typical;
    Effects e1, e2;
    applyEffects(v, in, e1);
    v[k] = 2.0 * t.typical;
    applyEffects(v, in, e2);
    const double d1[] = {e1.volume_factor - 1.0, e1.extra_mass_kg, e1.pitch_bias_rad, e1.roll_bias_rad,
                         e1.depth_offset_m, e1.vertical_current_mps, e1.roll_moment_nm, e1.pitch_moment_nm};
    const double d2[] = {e2.volume_factor - 1.0, e2.extra_mass_kg, e2.pitch_bias_rad, e2.roll_bias_rad,
                         e2.depth_offset_m, e2.vertical_current_mps, e2.roll_moment_nm, e2.pitch_moment_nm};
    int moved = 0;
    for (int f = 0; f < 8; ++f) {
      if (d1[f] == 0.0) continue;
      ++moved;
      EXPECT_NEAR(d2[f], 2.0 * d1[f], 1e-12 * std::abs(d1[f])) << t.id;
    }
    EXPECT_EQ(moved, 1) << t.id;
  }
  // Hand values: 3e-6 /dbar at 300 dbar = 0.9 per mille of volume; 3e-5 /degC at -8 degC.
  TermValues v{};
  v[*findTerm("hull_compressibility")] = 3e-6;
  v[*findTerm("thermal_expansion")] = 3e-5;
  v[*findTerm("mass_drift")] = 0.01;
  v[*findTerm("propeller_torque")] = 1e-6;
  Effects e;
  applyEffects(v, in, e);
  EXPECT_NEAR(e.volume_factor, (1.0 - 9e-4) * (1.0 - 2.4e-4), 1e-15);
  EXPECT_DOUBLE_EQ(e.extra_mass_kg, 0.02);
  EXPECT_DOUBLE_EQ(e.roll_moment_nm, 0.09);
}

TEST(PhysicsTerms, SimulatorAdjustmentCarriesEveryTerm) {
  TermValues v{};
  for (std::size_t k = 0; k < kTermCount; ++k) v[k] = termLibrary()[k].typical * static_cast<double>(k + 1);
  const SimAdjustment a = simAdjustment(v);
  EXPECT_DOUBLE_EQ(a.compressibility_per_dbar, v[*findTerm("hull_compressibility")]);
  EXPECT_DOUBLE_EQ(a.thermal_expansion_per_degC, v[*findTerm("thermal_expansion")]);
  EXPECT_DOUBLE_EQ(a.prop_torque_nm_per_rpm2, v[*findTerm("propeller_torque")]);
  EXPECT_DOUBLE_EQ(a.mass_drift_kg_per_h, v[*findTerm("mass_drift")]);
  EXPECT_DOUBLE_EQ(a.pitch_bias_rad, v[*findTerm("pitch_sensor_bias")]);
  EXPECT_DOUBLE_EQ(a.roll_bias_rad, v[*findTerm("roll_sensor_bias")]);
  EXPECT_DOUBLE_EQ(a.depth_offset_m, v[*findTerm("depth_sensor_offset")]);
  EXPECT_DOUBLE_EQ(a.pitch_damping_scale, v[*findTerm("quadratic_pitch_damping")]);
  EXPECT_DOUBLE_EQ(a.vertical_current_mps, v[*findTerm("vertical_current")]);
}

TEST(PhysicsTerms, AcceptedTermsAreReadFromTheProfileInDisplayUnits) {
  const nlohmann::json s = {{"model_check", {{"terms", {{"pitch_sensor_bias", 1.5}, {"vertical_current", 0.004}}}}}};
  const TermValues v = acceptedTermsFromProfile(s, "p.json");
  EXPECT_NEAR(v[*findTerm("pitch_sensor_bias")], 1.5 * std::acos(-1.0) / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(v[*findTerm("vertical_current")], 0.004);
  EXPECT_DOUBLE_EQ(v[*findTerm("mass_drift")], 0.0);
  const nlohmann::json bad = {{"model_check", {{"terms", {{"hull_stiffness", 1.0}}}}}};
  EXPECT_THROW(acceptedTermsFromProfile(bad, "p.json"), InputError);
  const nlohmann::json out = {{"model_check", {{"terms", {{"pitch_sensor_bias", 30.0}}}}}};
  EXPECT_THROW(acceptedTermsFromProfile(out, "p.json"), InputError);
}

}  // namespace
}  // namespace auv::discrepancy
