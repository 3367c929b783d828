// auvballast model-check --accept on an AUV whose hydrodynamics live in a
// companion file (HUGIN: resources/sim/hugin1000_hydrodynamics.json): the
// written profile is a whole vehicle, so 'analyze --vehicle P' identifies the
// net buoyancy from it (issue 11 item 7: it used to say "the log did not
// identify the net buoyancy"), and the report lists the calibration constants
// and never the propeller torque as missing physics (item 6).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace {

using auv::testing::runCli;

std::string tmp(const std::string& name) { return ::testing::TempDir() + std::to_string(::getpid()) + "_mc_cli_" + name; }

nlohmann::json readJson(const std::string& path) { return nlohmann::json::parse(std::ifstream(path)); }

TEST(ModelCheckCli, AcceptWritesAWholeVehicleThatAnalyzeUses) {
  const std::string plan = tmp("plan.json"), log = tmp("log.csv"), profile = tmp("hugin.model-check.json");
  // Four 400 s legs at three propeller speeds and four depths.
  std::ofstream(plan) << R"({
  "format": "auvballast-mission-plan", "version": 1, "vehicle": "hugin1000",
  "water": { "cast": [ { "depth_m": 0, "temperature_degC": 9, "salinity_psu": 34 },
                       { "depth_m": 100, "temperature_degC": 7, "salinity_psu": 35 } ], "max_depth_m": 150 },
  "installed_kg": [7.2, 7.2, 25.2, 25.2],
  "initial": { "depth_m": 30, "speed_mps": 2.0 },
  "legs": [ { "type": "depth", "depth_m": 30, "prop_demand": 130, "duration_s": 400 },
            { "type": "depth", "depth_m": 50, "prop_demand": 160, "duration_s": 400 },
            { "type": "depth", "depth_m": 40, "prop_demand": 190, "duration_s": 400 },
            { "type": "depth", "depth_m": 60, "prop_demand": 160, "duration_s": 400 } ],
  "options": { "trace_interval_s": 1.0, "seed": 5,
               "noise": { "depth_m": 0.02, "pitch_deg": 0.05, "roll_deg": 0.05, "speed_mps": 0.01 } }
})";
  ASSERT_EQ(runCli("simulate --vehicle hugin1000 --plan " + plan + " --out " + log).code, 0);
  const std::string installed = " --installed 7.2,7.2,25.2,25.2";
  const auto r = runCli("model-check --vehicle hugin1000 --log " + log + installed + " --accept --out-profile " + profile +
                        " --json " + tmp("mc.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json mc = readJson(tmp("mc.json"));
  for (const auto& m : mc["missing_physics"]) EXPECT_NE(m["id"], "propeller_torque");
  ASSERT_TRUE(mc["calibration"].is_array());
  bool torque = false;
  for (const auto& c : mc["calibration"]) {
    for (const char* key : {"id", "value", "unit", "sigma", "profile_value", "identified"}) EXPECT_TRUE(c.contains(key)) << key;
    if (c["id"] == "propeller_torque") {
      torque = true;
      // The simulated HUGIN has exactly its profile's torque: K_Q0 0.08, D 0.6 m.
      const double k = 1025.0 * 0.07776 * 0.08 / 3600.0;
      EXPECT_NEAR(c["profile_value"].get<double>(), k, 1e-6 * k);
      EXPECT_NEAR(c["value"].get<double>(), k, 0.05 * k);
    }
  }
  EXPECT_TRUE(torque);
  ASSERT_FALSE(mc["model_check"]["profile_written"].is_null());
  const nlohmann::json p = readJson(profile);
  for (const char* section : {"hydrodynamics", "actuators", "sim_assumptions", "autopilot"}) EXPECT_TRUE(p.contains(section)) << section;

  const auto a = runCli("analyze --vehicle " + profile + " --log " + log + installed + " --json -");
  ASSERT_EQ(a.code, 0) << a.err;
  const nlohmann::json aj = nlohmann::json::parse(a.out);
  ASSERT_TRUE(aj["net_buoyancy_kg"].is_number()) << a.out.substr(0, 400);
  EXPECT_EQ(a.out.find("did not identify the net buoyancy"), std::string::npos);
  // The truth at the start: +3.25 kg light (the simulator's own report for this plan and seed).
  EXPECT_NEAR(aj["net_buoyancy_kg"].get<double>(), 3.25, 0.5);
}

}  // namespace
