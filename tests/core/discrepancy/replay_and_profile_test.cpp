// The replay with term hooks against the simulator's own replay, the
// simulator knobs of the parameter terms, "model it" (accepted terms written
// into a profile copy and used from then on) and the JSON contract.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "analysis/analysis_report.h"
#include "delphin_test_log.h"
#include "analysis/mission_analysis.h"
#include "discrepancy/model_check_report.h"
#include "discrepancy/profile_update.h"
#include "discrepancy/synthetic_auv.h"
#include "discrepancy/synthetic_glider.h"
#include "discrepancy/term_replay.h"
#include "discrepancy/vehicle_check.h"
#include "sim/mission_plan.h"
#include "sim/replay.h"
#include "sim/water_from_log.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"
#include "vehicle/profile_writer.h"
#include "vehicle/vehicle_catalog.h"

namespace auv::discrepancy {
namespace {

const std::string kVehicles = std::string(AUV_RESOURCE_DIR) + "/vehicles/";

// A model-check result that found (and accepted) these terms, SI values.
ModelCheckResult resultWithTerms(std::initializer_list<std::pair<const char*, double>> terms) {
  ModelCheckResult r;
  for (const auto& [id, si] : terms) {
    const std::size_t k = *findTerm(id);
    r.accepted[k] = si;
    MissingPhysics m;
    m.id = id;
    m.unit = std::string(termLibrary()[k].unit);
    m.value = si * termLibrary()[k].display_scale;
    r.missing_physics.push_back(m);
  }
  return r;
}

struct Auv {
  VehicleProfile profile = loadVehicleProfile(kVehicles + "delphin2.json");
  sim::SimVehicle vehicle = sim::loadSimVehicle(profile, AUV_RESOURCE_DIR);
  MissionLog log;
  Auv() : log(test_logs::delphinTestLog(vehicle)) {}
};
const Auv& auvCase() {
  static const Auv a;
  return a;
}

TEST(TermReplay, WithoutHooksItIsTheSimulatorsReplay) {
  const Auv& a = auvCase();
  const sim::WaterColumn water = sim::waterColumnFromLog(a.log);
  sim::ReplayOptions ro;
  ro.drive = sim::ReplayDrive::DepthCommands;
  const sim::SimTrace ref = sim::replay(a.vehicle.model, a.vehicle.autopilot, water, a.log, ro);
  TermReplayOptions to;
  to.drive = sim::ReplayDrive::DepthCommands;
  to.preload_hover_integrator = false;  // sim::replay starts its integrators at zero
  const TermReplayTrace tr = termReplay(a.vehicle.model, a.vehicle.autopilot, water, a.log, {}, a.log.time, to);
  ASSERT_EQ(ref.size(), a.log.rowCount());
  for (std::size_t i = 0; i < ref.size(); i += 37) {
    EXPECT_NEAR(tr.depth_m[i], ref.depth_m[i], 1e-9);
    EXPECT_NEAR(tr.pitch_rad[i], ref.pitch_rad[i], 1e-9);
    EXPECT_NEAR(tr.roll_rad[i], ref.roll_rad[i], 1e-9);
    EXPECT_NEAR(tr.speed_mps[i], ref.speed_mps[i], 1e-9);
  }
}

TEST(TermReplay, SensorHooksActWhereTheSensorIsRead) {
  const Auv& a = auvCase();
  const sim::WaterColumn water = sim::waterColumnFromLog(a.log);
  TermReplayOptions to;
  const TermReplayTrace base = termReplay(a.vehicle.model, a.vehicle.autopilot, water, a.log, {}, a.log.time, to);
  SimAdjustment roll;
  roll.roll_bias_rad = 0.02;  // read by nobody but the log
  const TermReplayTrace r = termReplay(a.vehicle.model, a.vehicle.autopilot, water, a.log, roll, a.log.time, to);
  for (std::size_t i = 100; i < r.roll_rad.size(); i += 53) EXPECT_NEAR(r.roll_rad[i] - base.roll_rad[i], 0.02, 1e-9);
  // A depth offset is read by the autopilot too: it steers the reading to the
  // command, so the logged depth stays, the vehicle flies 0.5 m shallower.
  SimAdjustment off;
  off.depth_offset_m = 0.5;
  const TermReplayTrace d = termReplay(a.vehicle.model, a.vehicle.autopilot, water, a.log, off, a.log.time, to);
  double mean = 0.0;
  std::size_t n = 0;
  for (std::size_t i = d.depth_m.size() / 2; i < d.depth_m.size(); ++i, ++n) mean += d.depth_m[i] - base.depth_m[i];
  EXPECT_LT(std::abs(mean / static_cast<double>(n)), 0.05);
}

TEST(TermReplay, ParameterTermsChangeTheModel) {
  const sim::VehicleModel& m = auvCase().vehicle.model;
  SimAdjustment a;
  a.prop_torque_nm_per_rpm2 = 2e-6;
  a.pitch_damping_scale = 1.0;
  a.compressibility_per_dbar = 4e-6;
  const sim::VehicleModel x = adjustedModel(m, a);
  // Reaction torque at bollard pull, rho 1025: rho n^2 D^5 K_Q0 with n in rev/s.
  const double dKQ = x.prop.torque_sign * x.prop.KQ0 - m.prop.torque_sign * m.prop.KQ0;
  EXPECT_NEAR(1025.0 * std::pow(m.prop.diameter_m, 5) * dKQ / 3600.0, 2e-6, 1e-15);
  EXPECT_DOUBLE_EQ(x.hydro.Mqq_kgm2, 2.0 * m.hydro.Mqq_kgm2);
  EXPECT_DOUBLE_EQ(x.body.hull.compressibility_per_dbar, m.body.hull.compressibility_per_dbar + 4e-6);
}

TEST(ProfileUpdate, TermsGoWhereTheLoadersReadThem) {
  const Auv& a = auvCase();
  const ModelCheckResult r = resultWithTerms(
      {{"propeller_torque", 2e-6}, {"quadratic_pitch_damping", 0.5}, {"hull_compressibility", 3e-6}, {"vertical_current", 0.004}});
  const nlohmann::json doc = JsonReader::parseFile(a.profile.file);
  const nlohmann::json out = profileWithAcceptedTerms(doc, a.profile, r, "demo.csv");
  EXPECT_DOUBLE_EQ(out["hull"]["compressibility_per_dbar"].get<double>(), 3e-6);
  EXPECT_DOUBLE_EQ(out["hydrodynamics"]["Mqq_kgm2_per_rad2"].get<double>(), 1.5 * doc["hydrodynamics"]["Mqq_kgm2_per_rad2"].get<double>());
  EXPECT_DOUBLE_EQ(out["model_check"]["terms"]["vertical_current"].get<double>(), 0.004);
  EXPECT_EQ(out["model_check"]["accepted"].size(), 4u);
  EXPECT_EQ(out["model_check"]["accepted"][0]["log"], "demo.csv");
  // The simulator reads the new profile.
  const VehicleProfile v2 = parseVehicleProfile(out.dump(), "copy.json");
  const sim::SimVehicle s2 = sim::loadSimVehicle(v2, AUV_RESOURCE_DIR);
  const sim::VehicleModel& m0 = a.vehicle.model;
  EXPECT_NEAR(1025.0 * std::pow(m0.prop.diameter_m, 5) * (s2.model.prop.KQ0 - m0.prop.KQ0) / 3600.0, 2e-6, 1e-15);
  EXPECT_DOUBLE_EQ(s2.model.body.hull.compressibility_per_dbar, 3e-6);
  EXPECT_DOUBLE_EQ(acceptedTermsFromProfile(v2.sections, v2.file)[*findTerm("vertical_current")], 0.004);
}

// The loop of issue 5 on a glider: find, write into the profile, check again
// with the new profile: nothing is missing any more, and the simulation
// error is what the accepted fit promised.
TEST(ModelIt, AnAcceptedTermIsUsedFromThenOn) {
  const VehicleProfile v = loadVehicleProfile(kVehicles + "slocum_g2.json");
  SyntheticGliderTruth t;
  t.constants.mass_kg = v.mass_kg;
  t.constants.thermal_expansion_per_degC = v.hull.thermal_expansion_per_degC;
  t.constants.reference_temperature_degC = v.hull.reference_temperature_degC;
  t.constants.compressibility_per_dbar = 6e-6;
  SyntheticGliderMission m;
  m.seed = 31;
  const MissionLog log = synthesizeGliderLog(t, m);
  const auto first = runModelCheck(*makeCheckModel(log, v, AUV_RESOURCE_DIR));
  ASSERT_EQ(first.missing_physics.size(), 1u);
  ASSERT_EQ(first.missing_physics[0].id, "hull_compressibility");
  const nlohmann::json doc = profileWithAcceptedTerms(JsonReader::parseFile(v.file), v, first, "synthetic.csv");
  const VehicleProfile v2 = parseVehicleProfile(doc.dump(), "slocum_g2.model-check.json");
  EXPECT_DOUBLE_EQ(v2.hull.compressibility_per_dbar, first.accepted[*findTerm("hull_compressibility")]);
  const auto second = runModelCheck(*makeCheckModel(log, v2, AUV_RESOURCE_DIR));
  EXPECT_TRUE(second.missing_physics.empty());
  EXPECT_NEAR(second.net_buoyancy_kg, first.net_buoyancy_kg, 3.0 * first.net_buoyancy_sigma_kg + 1e-3);
  for (const ChannelRms& c : second.rms)
    if (c.source == "simulation" && c.channel == Channel::kVerticalVelocity) {
      for (const ChannelRms& f : first.rms)
        if (f.source == c.source && f.channel == c.channel) {
          EXPECT_NEAR(c.fitted_before, f.fitted_after, 0.02 * f.fitted_after);
        }
    }
  // The analysis reads the hull compressibility from the copy too.
  const analysis::AnalysisReport ar = analysis::analyzeMission(log, v2);
  EXPECT_DOUBLE_EQ(ar.details["glider_fit"]["constants"]["compressibility_per_dbar"].get<double>(), v2.hull.compressibility_per_dbar);
}

TEST(ModelIt, OnlyTheTermsTheTechnicianAcceptsReachTheVehicle) {
  // Two terms found; the technician keeps one. The returned vehicle has
  // that one, the rejected one is nowhere, and the companion sections
  // (HUGIN's hydrodynamics live in resources/sim) are still there.
  const VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000");
  ASSERT_TRUE(v.sections.contains("hydrodynamics"));
  const ModelCheckResult r = resultWithTerms({{"hull_compressibility", 3e-6}, {"vertical_current", 0.004}});
  nlohmann::json stored;
  const VehicleProfile kept = vehicleWithAcceptedTerms(JsonReader::parseFile(v.file), v, r, {"hull_compressibility"},
                                                       "survey.csv", &stored);
  EXPECT_DOUBLE_EQ(kept.hull.compressibility_per_dbar, v.hull.compressibility_per_dbar + 3e-6);
  EXPECT_EQ(stored["model_check"]["accepted"].size(), 1u);
  EXPECT_FALSE(stored["model_check"].contains("terms"));  // vertical_current rejected
  EXPECT_TRUE(kept.sections.contains("hydrodynamics"));
  // What the history stores loads back to the same vehicle.
  const VehicleProfile again = vehicleFromStoredProfile(stored, VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000"), "history");
  EXPECT_DOUBLE_EQ(again.hull.compressibility_per_dbar, kept.hull.compressibility_per_dbar);
  EXPECT_DOUBLE_EQ(again.hull.volumeAt(8.0, 300.0), kept.hull.volumeAt(8.0, 300.0));
  EXPECT_LT(again.hull.volumeAt(8.0, 300.0), v.hull.volumeAt(8.0, 300.0));  // compresses more at depth
  EXPECT_TRUE(again.sections.contains("hydrodynamics"));
  // Nothing accepted: the vehicle as it was.
  const VehicleProfile none = vehicleWithAcceptedTerms(JsonReader::parseFile(v.file), v, r, {}, "survey.csv");
  EXPECT_DOUBLE_EQ(none.hull.compressibility_per_dbar, v.hull.compressibility_per_dbar);
}

// Issue 11 item 7: what --accept writes is a whole vehicle (HUGIN's companion
// hydrodynamics included, readable without resources/sim), the identified
// calibration constants go where the simulator reads them, constants the log
// did not identify stay as they were, and the written profile round-trips.
TEST(ProfileUpdate, CalibratedConstantsGoIntoACompleteProfile) {
  const VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000");
  const sim::SimVehicle nominal = sim::loadSimVehicle(v, AUV_RESOURCE_DIR);
  const sim::Propeller& p = nominal.model.prop;
  const double perKQ = 1025.0 * std::pow(p.diameter_m, 5) / 3600.0;
  ModelCheckResult r;
  auto cal = [&](const char* id, double value, double profile, bool identified) {
    CalibrationValue c;
    c.id = id;
    c.value = value;
    c.profile_value = profile;
    c.sigma = 0.01 * std::abs(profile);
    c.identified = identified;
    r.calibration.push_back(c);
  };
  cal("propeller_torque", 0.25 * perKQ * p.KQ0, perKQ * p.KQ0, true);  // a quarter of the assumed torque
  cal("heave_derivatives", 1.3, 1.0, true);
  // Munk inside the tabulated M_w: the net derivative is M_w' alone.
  const double L = 5.23, munk = (-47.0 + 1490.0) / (0.5 * 1025.0 * L * L * L);
  cal("net_pitch_moment_derivative", -4.5e-3, -4.5e-3 + munk, true);
  cal("stern_plane_effectiveness", 0.7, 1.0, false);  // stayed at its prior: not written
  const nlohmann::json out = profileWithAcceptedTerms(profileToJson(v), v, r, "survey.csv");
  EXPECT_EQ(out["model_check"]["calibrated"].size(), 3u);
  const VehicleProfile w = parseVehicleProfile(out.dump(), "/nowhere/hugin1000.model-check.json");
  ASSERT_TRUE(w.sections.contains("hydrodynamics"));
  const sim::SimVehicle s = sim::loadSimVehicle(w, "/nonexistent-resource-dir");  // no companion lookup
  EXPECT_NEAR(s.model.prop.KQ0, 0.25 * p.KQ0, 1e-12);
  EXPECT_NEAR(s.model.hydro.Zw_prime, 1.3 * nominal.model.hydro.Zw_prime, 1e-15);
  EXPECT_NEAR(s.model.hydro.Zww_kg_per_m, 1.3 * nominal.model.hydro.Zww_kg_per_m, 1e-9);
  // The simulator's M_w' is the net less (X_udot - Z_wdot) / (0.5 rho L^3), from the companion's numbers.
  EXPECT_NEAR(s.model.hydro.Mw_prime, -4.5e-3 - munk, 1e-12);
  EXPECT_EQ(s.model.planes.M_uud_per_deg, nominal.model.planes.M_uud_per_deg);
  // Load -> write -> load of the written profile: the same vehicle, hydrodynamics included.
  const VehicleProfile again = parseVehicleProfile(profileToJson(w).dump(), "again.json");
  EXPECT_EQ(profileToJson(again), profileToJson(w));
  EXPECT_EQ(again.sections["hydrodynamics"], w.sections["hydrodynamics"]);
}

TEST(ModelCheckJson, TheContractFieldsAreThere) {
  const VehicleProfile v = loadVehicleProfile(kVehicles + "slocum_g2.json");
  SyntheticGliderTruth t;
  t.constants.mass_kg = v.mass_kg;
  t.constants.thermal_expansion_per_degC = v.hull.thermal_expansion_per_degC;
  t.constants.reference_temperature_degC = v.hull.reference_temperature_degC;
  t.constants.compressibility_per_dbar = 6e-6;
  SyntheticGliderMission m;
  m.seed = 31;
  const MissionLog log = synthesizeGliderLog(t, m);
  const ModelCheckResult r = runModelCheck(*makeCheckModel(log, v, AUV_RESOURCE_DIR));
  nlohmann::json a = analysis::toJson(analysis::analyzeMission(log, v));
  const nlohmann::json before = a["net_buoyancy_kg"];
  mergeIntoAnalysisJson(a, r);
  ASSERT_TRUE(a["missing_physics"].is_array());
  ASSERT_EQ(a["missing_physics"].size(), 1u);
  const nlohmann::json& mp = a["missing_physics"][0];
  for (const char* key : {"id", "value", "unit", "sigma", "rms_before", "rms_after", "channel", "where"})
    EXPECT_TRUE(mp.contains(key)) << key;
  EXPECT_EQ(mp["id"], "hull_compressibility");
  EXPECT_EQ(mp["unit"], "1/dbar");
  EXPECT_TRUE(mp["value"].is_number());
  EXPECT_TRUE(mp["where"].is_string());
  EXPECT_LT(mp["rms_after"].get<double>(), mp["rms_before"].get<double>());
  EXPECT_NEAR(a["net_buoyancy_kg"].get<double>(), r.net_buoyancy_kg, 1e-6);
  EXPECT_EQ(a["model_check"]["analysis_estimate"]["net_buoyancy_kg"], before);
  EXPECT_TRUE(a["cg_offset_mm"].is_object());
  EXPECT_TRUE(a["model_check"]["rms"].is_array());
  EXPECT_TRUE(a["model_check"]["localisation"].is_array());
  EXPECT_TRUE(a["model_check"]["identifiability"].is_array());
}

}  // namespace
}  // namespace auv::discrepancy
