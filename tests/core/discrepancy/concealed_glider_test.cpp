// Proof on concealed effects, glider terms: the steady-glide model flown
// forward in time is the truth (synthetic_glider.h), with one effect the
// analysis model lacks, hidden by internal-wave vertical velocity (0.8 cm/s),
// sensor noise, pitch wander and a ballast error; several seeds each. The
// check must name the effect, fit it within 30 %, name nothing else, and
// lower the held-out simulation error. Rates are printed for the decision
// note (docs/decisions/model-check-proof.md).
#include <gtest/gtest.h>

#include "concealed_harness.h"
#include "discrepancy/glider_check_model.h"
#include "discrepancy/synthetic_glider.h"
#include "vehicle/profile_loader.h"

namespace auv::discrepancy {
namespace {

using test::runConcealedCase;

const std::vector<std::uint64_t> kSeeds = {101, 202, 303, 404};

const VehicleProfile& slocum() {
  static const VehicleProfile v = loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/slocum_g2.json");
  return v;
}

// The truth vehicle = the profile (compressibility 0, thermal expansion 7e-5)
// plus whatever the case switches on.
SyntheticGliderTruth baseTruth() {
  SyntheticGliderTruth t;
  t.constants.mass_kg = slocum().mass_kg;
  t.constants.thermal_expansion_per_degC = slocum().hull.thermal_expansion_per_degC;
  t.constants.reference_temperature_degC = slocum().hull.reference_temperature_degC;
  t.constants.compressibility_per_dbar = 0.0;
  t.net_buoyancy_kg = 0.08;  // the ballast error, always estimated
  return t;
}

std::function<std::unique_ptr<CheckModel>(std::uint64_t)> factory(const SyntheticGliderTruth& truth,
                                                                 SyntheticGliderMission mission) {
  return [truth, mission](std::uint64_t seed) mutable {
    mission.seed = seed;
    const MissionLog log = synthesizeGliderLog(truth, mission);
    return std::unique_ptr<CheckModel>(new GliderCheckModel(log, slocum()));
  };
}

TEST(ConcealedGlider, ControlFindsNothing) {
  SyntheticGliderMission m;
  m.pump_climb_cm3 = {250.0, 150.0};
  const auto o = runConcealedCase("glider control", "", 0.0, kSeeds, factory(baseTruth(), m));
  EXPECT_EQ(o.false_positives, 0);
}

TEST(ConcealedGlider, HullCompressibilityInAThermocline) {
  SyntheticGliderTruth t = baseTruth();
  t.constants.compressibility_per_dbar = 5e-6;  // 39 g at 150 dbar against an 80 g ballast error
  SyntheticGliderMission m;
  m.yos = 16;
  test::expectAllFound(runConcealedCase("hull_compressibility", "hull_compressibility", 5e-6, kSeeds, factory(t, m)));
}

TEST(ConcealedGlider, ThermalExpansionBeyondTheProfiles) {
  SyntheticGliderTruth t = baseTruth();
  t.constants.thermal_expansion_per_degC += 5e-5;  // the profile has 7e-5; the hull is really 1.2e-4
  SyntheticGliderMission m;  // tropical: 24 -> 8 degC, the thermocline heaving +-15 m between yos
  m.surface_temperature_degC = 24.0;
  m.yos = 12;
  test::expectAllFound(runConcealedCase("thermal_expansion", "thermal_expansion", 5e-5, kSeeds, factory(t, m)));
}

TEST(ConcealedGlider, MassDrift) {
  SyntheticGliderTruth t = baseTruth();
  t.mass_drift_kg_per_h = 0.012;  // +-35 g over the mission against an 80 g ballast error
  test::expectAllFound(runConcealedCase("mass_drift", "mass_drift", 0.012, kSeeds, factory(t, {})));
}

TEST(ConcealedGlider, PitchSensorBias) {
  SyntheticGliderTruth t = baseTruth();
  t.pitch_bias_deg = 2.0;
  SyntheticGliderMission m;
  m.pitch_dive_deg = {-18.0, -30.0};  // the separating manoeuvre: two pitch angles
  m.pitch_climb_deg = {20.0, 28.0};
  test::expectAllFound(runConcealedCase("pitch_sensor_bias", "pitch_sensor_bias", 2.0, kSeeds, factory(t, m)));
}

TEST(ConcealedGlider, DepthSensorOffset) {
  SyntheticGliderTruth t = baseTruth();
  t.depth_offset_m = 0.3;
  SyntheticGliderMission m;
  m.depth_noise_m = 0.2;
  test::expectAllFound(runConcealedCase("depth_sensor_offset", "depth_sensor_offset", 0.3, kSeeds, factory(t, m)));
}

TEST(ConcealedGlider, VerticalCurrent) {
  SyntheticGliderTruth t = baseTruth();
  // 1 cm/s of upwelling: with equal pump volumes on dives and climbs and one
  // pitch angle it is a net-buoyancy error (and a pitch bias); the log
  // carries the separating manoeuvres: climbs on 60 and 150 cm3 against
  // 250 cm3 dives, and two pitch angles.
  t.vertical_current_mps = 0.01;
  SyntheticGliderMission m;
  m.yos = 16;
  m.internal_wave_sigma_mps = 0.005;
  m.pump_climb_cm3 = {60.0, 150.0};
  m.pitch_dive_deg = {-15.0, -30.0};
  m.pitch_climb_deg = {15.0, 30.0};
  test::expectAllFound(runConcealedCase("vertical_current", "vertical_current", 0.01, kSeeds, factory(t, m)));
}

}  // namespace
}  // namespace auv::discrepancy
