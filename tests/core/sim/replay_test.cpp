// Replay: a simulated log driven back through the model with its own
// recorded actuators or commands reproduces the run (the model check's
// zero-difference baseline); from a coarser log it stays close; bad logs are
// refused naming the channel.
#include "sim/replay.h"

#include <unistd.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "missionlog/interchange_csv.h"
#include "sim/sim_log.h"
#include "sim/simulator.h"
#include "sim/water_from_log.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

using testing::HuginSim;

struct Recorded {
  Scenario scenario;
  SimTrace trace;
  MissionLog log;  // as read back from the CSV file
};

Scenario huginManoeuvres(const HuginSim& h) {
  Scenario sc;
  sc.extra_masses = installedWeights(h.profile, testing::huginInstalledKg());
  sc.ballast_error.net_buoyancy_kg = 2.0;
  sc.initial_depth_m = 30.0;
  sc.initial_speed_mps = 1.8;
  sc.legs = {{60.0, 30.0, 160.0}, {90.0, 45.0, 140.0, 0.0, units::degToRad(60.0)}, {60.0, 40.0, 120.0}};
  return sc;
}

Recorded record(const HuginSim& h, const WaterColumn& water, double interval) {
  Recorded r;
  r.scenario = huginManoeuvres(h);
  SimOptions o;
  o.trace_interval_s = interval;
  r.trace = simulate(h.model(), h.autopilot(), water, r.scenario, o);
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_replay_test.csv";
  writeSimulatedLog(r.trace, {"hugin1000", "plan", "", 1, 0, {}, {}}, path);
  r.log = readInterchangeCsv(path);
  return r;
}

double rms(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / static_cast<double>(a.size()));
}

double maxAbs(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

class ReplayOwnLog : public ::testing::TestWithParam<ReplayDrive> {};

TEST_P(ReplayOwnLog, ReproducesTheRunStepForStep) {
  const HuginSim h;
  const WaterColumn sea = testing::huginSea();
  const Recorded r = record(h, sea, 0.05);  // every model step
  ASSERT_EQ(r.log.rowCount(), 4201u);
  ReplayOptions ro;
  ro.drive = GetParam();
  ro.loading = r.scenario.loading();
  const SimTrace b = replay(h.model(), h.autopilot(), sea, r.log, ro);
  ASSERT_EQ(b.size(), r.trace.size());
  EXPECT_EQ(b.time_s, r.trace.time_s);
  // The only differences are the last bits lost converting rad <-> deg and
  // rev/s <-> rpm through the file.
  EXPECT_LT(rms(b.depth_m, r.trace.depth_m), 1e-9);
  EXPECT_LT(maxAbs(b.depth_m, r.trace.depth_m), 1e-8);
  EXPECT_LT(maxAbs(b.pitch_rad, r.trace.pitch_rad), 1e-10);
  EXPECT_LT(maxAbs(b.speed_mps, r.trace.speed_mps), 1e-10);
  EXPECT_LT(maxAbs(b.heading_rad, r.trace.heading_rad), 1e-9);
  EXPECT_LT(maxAbs(b.elevator_rad, r.trace.elevator_rad), 1e-10);
  EXPECT_EQ(b.truth.mass_kg, r.trace.truth.mass_kg);
  // And the run is not trivial: it dived 15 m and turned 60 degrees.
  EXPECT_GT(r.trace.depth_m[3000], 44.0);
  EXPECT_NEAR(units::radToDeg(r.trace.heading_rad.back()), 60.0, 1.0);
}

INSTANTIATE_TEST_SUITE_P(AllDrives, ReplayOwnLog,
                         ::testing::Values(ReplayDrive::Auto, ReplayDrive::Actuators, ReplayDrive::PitchCommands,
                                           ReplayDrive::DepthCommands),
                         [](const auto& p) { return replayDriveName(p.param); });

TEST(Replay, CoarseLogStaysCloseAndCommandsBeatInterpolatedActuators) {
  const HuginSim h;
  const WaterColumn sea = testing::huginSea();
  const Recorded r = record(h, sea, 1.0);  // a typical 1 Hz log
  ReplayOptions ro;
  ro.loading = r.scenario.loading();
  const SimTrace act = replay(h.model(), h.autopilot(), sea, r.log, ro);
  ro.drive = ReplayDrive::DepthCommands;
  const SimTrace cmd = replay(h.model(), h.autopilot(), sea, r.log, ro);
  ASSERT_EQ(act.size(), 211u);
  // Linear interpolation of a 1 Hz elevator misses the fin's slews a little
  // and the error integrates open loop; the closed loop on the recorded depth
  // commands only sees the interpolated propeller and rudder.
  const double e_act = rms(act.depth_m, r.trace.depth_m), e_cmd = rms(cmd.depth_m, r.trace.depth_m);
  std::printf("1 Hz replay, RMS depth difference: actuators %.4f m, depth commands %.5f m\n", e_act, e_cmd);
  EXPECT_LT(e_act, 0.1);
  EXPECT_LT(e_cmd, 0.005);
  EXPECT_LT(e_cmd, e_act);
}

TEST(Replay, HoverVehicleReplaysItsThrusters) {
  const testing::Delphin2 d;
  Scenario sc;
  sc.net_buoyancy_n = 6.0;
  sc.legs = {{30.0, 1.0, 0.0}, {30.0, 2.0, 0.0}};
  SimOptions o;
  o.trace_interval_s = 0.05;
  const WaterColumn tank = WaterColumn::uniform(1000.0);
  const SimTrace a = simulate(d.model, d.autopilot, tank, sc, o);
  const MissionLog log = toMissionLog(a, {"delphin2", "plan", "", 1, 2, {}, {}});
  ReplayOptions ro;
  ro.loading = sc.loading();
  EXPECT_EQ(resolveReplayDrive(d.model, log, ReplayDrive::Auto), ReplayDrive::Actuators);
  const SimTrace b = replay(d.model, d.autopilot, tank, log, ro);
  EXPECT_LT(maxAbs(b.depth_m, a.depth_m), 1e-9);
  EXPECT_GT(a.depth_m.back(), 1.9);
  // Without the thruster channels the actuators cannot be replayed.
  MissionLog no_thrusters = log;
  std::erase_if(no_thrusters.channels, [](const LogChannel& c) { return c.name.starts_with("thruster"); });
  EXPECT_EQ(resolveReplayDrive(d.model, no_thrusters, ReplayDrive::Auto), ReplayDrive::PitchCommands);
}

TEST(Replay, RefusesLogsItCannotDriveNamingTheChannel) {
  const HuginSim h;
  const WaterColumn sea = testing::huginSea();
  const Recorded r = record(h, sea, 1.0);
  auto fieldOf = [&](MissionLog log, ReplayDrive drive) {
    try {
      ReplayOptions ro;
      ro.drive = drive;
      (void)replay(h.model(), h.autopilot(), sea, log, ro);
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("no error");
  };
  auto without = [&](std::initializer_list<const char*> names) {
    MissionLog log = r.log;
    for (const char* n : names) std::erase_if(log.channels, [&](const LogChannel& c) { return c.name == n; });
    return log;
  };
  EXPECT_EQ(fieldOf(without({"prop_rpm"}), ReplayDrive::Auto), "prop_rpm");
  EXPECT_EQ(fieldOf(without({"elevator", "pitch_cmd", "depth_cmd"}), ReplayDrive::Auto), "elevator");
  EXPECT_EQ(fieldOf(without({"pitch_cmd"}), ReplayDrive::PitchCommands), "pitch_cmd");
  EXPECT_EQ(fieldOf(r.log, ReplayDrive::Auto), "no error");
  EXPECT_THROW((void)parseReplayDrive("elevators"), InputError);
}

TEST(WaterFromLog, RecoversTheCastTheMissionFlewThrough) {
  const HuginSim h;
  const WaterColumn sea = testing::huginSea();
  const Recorded r = record(h, sea, 1.0);
  const WaterColumn w = waterColumnFromLog(r.log, 1.0, 60.0);
  // The log sampled 30-45 m: there the binned T/S give the cast's density
  // (EOS-80 with pressure) to the T/S gradient across a 1 m bin.
  for (double z : {30.0, 37.5, 44.0}) {
    EXPECT_NEAR(w.at(z).density_kgm3, sea.at(z).density_kgm3, 2e-3) << z;
    EXPECT_NEAR(w.at(z).pressure_dbar, sea.at(z).pressure_dbar, 0.05) << z;
  }
  MissionLog no_ctd = r.log;
  std::erase_if(no_ctd.channels, [](const LogChannel& c) { return c.name == "salinity"; });
  try {
    (void)waterColumnFromLog(no_ctd);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "salinity");
  }
}

}  // namespace
}  // namespace auv::sim
