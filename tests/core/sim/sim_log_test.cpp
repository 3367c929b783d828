// A simulated mission written as the interchange CSV: what is read back is
// the trace, channel by channel, in the format's units and signs, with the
// truth in the metadata, and the same seed writes the same file.
#include "sim/sim_log.h"

#include <unistd.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "common/units.h"
#include "missionlog/interchange_csv.h"
#include "sim/simulator.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

using testing::HuginSim;

Scenario huginTurnAndDive(const HuginSim& h) {
  Scenario sc;
  sc.extra_masses = installedWeights(h.profile, testing::huginInstalledKg());
  sc.initial_depth_m = 20.0;
  sc.initial_speed_mps = 2.0;
  sc.legs = {{60.0, 20.0, 160.0}, {60.0, 30.0, 140.0, 0.0, units::degToRad(90.0)}};
  return sc;
}

SimOptions noisy(std::uint64_t seed, double interval = 1.0) {
  SimOptions o;
  o.trace_interval_s = interval;
  o.seed = seed;
  o.noise.depth_m = 0.02;
  o.noise.pitch_rad = units::degToRad(0.05);
  o.noise.roll_rad = units::degToRad(0.05);
  o.noise.heading_rad = units::degToRad(0.1);
  o.noise.speed_mps = 0.01;
  o.noise.temperature_degC = 0.002;
  return o;
}

double metaNumber(const MissionLog& log, const char* key) {
  const std::string* v = log.metadataValue(key);
  return v ? std::stod(*v) : std::nan("");
}

TEST(SimLog, CsvReadsBackAsTheTraceInLogUnits) {
  const HuginSim h;
  const SimTrace tr = simulate(h.model(), h.autopilot(), testing::huginSea(), huginTurnAndDive(h), noisy(5));
  ASSERT_EQ(tr.size(), 121u);
  SimLogInfo info{"hugin1000", "plan", "test.plan.json", 5, 0, testing::huginInstalledKg(), {}};
  const MissionLog log = toMissionLog(tr, info);
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_sim_log_test.csv";
  writeInterchangeCsv(log, path);
  const MissionLog back = readInterchangeCsv(path);

  ASSERT_EQ(back.rowCount(), tr.size());
  std::set<std::string> names;
  for (const LogChannel& c : back.channels) names.insert(c.name + " [" + c.unit + "]");
  const std::set<std::string> expected = {
      "depth [m]",       "depth_cmd [m]", "pitch [deg]",     "pitch_cmd [deg]",   "roll [deg]",
      "heading [deg]",   "heading_cmd [deg]", "speed [m/s]", "prop_rpm [rpm]",    "elevator [deg]",
      "rudder [deg]",    "temperature [degC]", "salinity [PSU]", "pressure [dbar]", "power [W]"};
  EXPECT_EQ(names, expected);  // HUGIN has no tunnel thrusters

  const double deg = 180.0 / std::numbers::pi;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    EXPECT_EQ(back.time[i], tr.time_s[i]);  // shortest round-trip numbers: exact
    EXPECT_EQ(back.channel("depth").values[i], tr.depth_m[i]);
    EXPECT_EQ(back.channel("speed").values[i], tr.speed_mps[i]);
    EXPECT_EQ(back.channel("prop_rpm").values[i], tr.prop_rpm[i]);
    EXPECT_NEAR(back.channel("pitch").values[i], tr.pitch_rad[i] * deg, 1e-12);
    EXPECT_NEAR(back.channel("elevator").values[i], tr.elevator_rad[i] * deg, 1e-12);
    EXPECT_NEAR(back.channel("heading").values[i], tr.heading_rad[i] * deg, 1e-11);
    EXPECT_EQ(back.channel("temperature").values[i], tr.temperature_degC[i]);
  }
  // Heading command: 90 deg on the second leg; heading within the format's 0..360.
  EXPECT_DOUBLE_EQ(back.channel("heading_cmd").values.back(), 90.0);
  for (double v : back.channel("heading").values) {
    EXPECT_GE(v, 0.0);
    EXPECT_LT(v, 360.0);
  }

  EXPECT_EQ(*back.metadataValue("vehicle"), "hugin1000");
  EXPECT_EQ(*back.metadataValue("source"), "auvballast simulate");
  EXPECT_EQ(*back.metadataValue("seed"), "5");
  EXPECT_EQ(*back.metadataValue("installed_kg"), "7.2,7.2,25.7,25.7");
  // Truth: the kit pieces on the profile mass, net buoyancy at the first sample.
  EXPECT_DOUBLE_EQ(metaNumber(back, "truth_mass_kg"), 1498.0 + 65.8);
  EXPECT_EQ(metaNumber(back, "truth_net_buoyancy_kg"), tr.truth.net_buoyancy_start_n / units::g0);
  EXPECT_NEAR(metaNumber(back, "truth_net_buoyancy_kg"), tr.net_buoyancy_n.front() / units::g0, 1e-12);
  EXPECT_EQ(metaNumber(back, "truth_cg_z_mm"), 1e3 * tr.truth.cg_z_m);
}

TEST(SimLog, SameSeedSameFileOtherSeedOtherFile) {
  const HuginSim h;
  const WaterColumn sea = testing::huginSea();
  const Scenario sc = huginTurnAndDive(h);
  auto text = [&](std::uint64_t seed) {
    const SimTrace tr = simulate(h.model(), h.autopilot(), sea, sc, noisy(seed));
    std::ostringstream out;
    writeInterchangeCsv(toMissionLog(tr, {"hugin1000", "plan", "", seed, 0, {}, {}}), out);
    return out.str();
  };
  const std::string a = text(11), b = text(11), c = text(12);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_GT(a.size(), 10000u);
}

TEST(SimLog, OutputRateAndCtdNoiseAreAsAsked) {
  const HuginSim h;
  const WaterColumn sea = testing::huginSea();
  const Scenario sc = huginTurnAndDive(h);
  SimOptions quiet;
  quiet.trace_interval_s = 0.5;
  SimOptions loud = noisy(3, 0.5);
  loud.noise = {};
  loud.noise.temperature_degC = 0.01;
  const MissionLog a = toMissionLog(simulate(h.model(), h.autopilot(), sea, sc, quiet), {});
  const MissionLog b = toMissionLog(simulate(h.model(), h.autopilot(), sea, sc, loud), {});
  ASSERT_EQ(a.rowCount(), 241u);  // 120 s at 2 Hz, both ends
  EXPECT_DOUBLE_EQ(a.time[1] - a.time[0], 0.5);
  // CTD noise only touches the logged temperature, not the flight.
  EXPECT_EQ(a.channel("depth").values, b.channel("depth").values);
  double sum2 = 0.0;
  for (std::size_t i = 0; i < a.rowCount(); ++i)
    sum2 += std::pow(b.channel("temperature").values[i] - a.channel("temperature").values[i], 2);
  EXPECT_NEAR(std::sqrt(sum2 / 241.0), 0.01, 0.0015);  // 3 sigma of the sample std for n = 241
}

TEST(SimLog, HoverVehicleLogsItsThrusters) {
  const testing::Delphin2 d;
  Scenario sc;
  sc.net_buoyancy_n = 6.0;
  sc.legs = {{90.0, 1.0, 0.0}};  // settled: the paper's fig. 14b settles within 15 s
  const SimTrace tr = simulate(d.model, d.autopilot, WaterColumn::uniform(1000.0), sc);
  EXPECT_NEAR(tr.depth_m.back(), 1.0, 0.005);
  const MissionLog log = toMissionLog(tr, {"delphin2", "plan", "", 1, d.model.thruster_count, {}, {}});
  ASSERT_TRUE(log.has("thruster_front_rpm"));
  EXPECT_EQ(log.channel("thruster_aft_rpm").values, tr.thruster_aft_rpm);
  EXPECT_FALSE(log.has("heading_cmd"));  // Delphin2's autopilot has no heading hold
  // Holding +6 N at rest: the static thrust of eq. 16 from the logged rpm
  // carries the net buoyancy.
  const TunnelThruster& t = d.model.thrusters[0];
  double F = 0.0;
  for (const char* name : {"thruster_front_rpm", "thruster_aft_rpm"}) {
    const double n = log.channel(name).values.back();
    F += 1000.0 * std::abs(n) * n * std::pow(t.diameter_m, 4) * t.KT_per_rpm2;
  }
  EXPECT_NEAR(F, 6.0, 0.05);
}

}  // namespace
}  // namespace auv::sim
