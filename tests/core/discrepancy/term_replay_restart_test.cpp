// Where the model check's replay restarts from the log: a surface interval
// ends a span as a drop-out does (the model has no waves and no surface
// behaviour), and a restart mid-dive begins with the logged depth rate and
// actuators, not at rest. With the surface model a vehicle that breaks the
// surface floats there, in the synthetic truth and in the replay.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "discrepancy/synthetic_auv.h"
#include "discrepancy/term_replay.h"
#include "sim/mission_plan.h"
#include "sim/water_from_log.h"
#include "vehicle/profile_loader.h"

namespace auv::discrepancy {
namespace {

struct Dive {
  VehicleProfile profile = loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/delphin2.json");
  sim::SimVehicle vehicle = sim::loadSimVehicle(profile, AUV_RESOURCE_DIR);
  MissionLog log;
  Dive() {
    SyntheticAuvTruth t;
    t.ballast_error.net_buoyancy_kg = 0.2;
    SyntheticAuvMission m;
    m.legs_count = 3;
    m.leg_s = 200.0;
    m.depths_m = {6.0, 30.0, 9.0};
    m.seed = 7;
    log = synthesizeAuvLog(vehicle, "delphin2", t, m);
  }
};
const Dive& dive() {
  static const Dive d;
  return d;
}

std::size_t rowAt(const MissionLog& log, double t) {
  std::size_t r = 0;
  while (r + 1 < log.rowCount() && log.time[r] < t) ++r;
  return r;
}

// The log with its depth reading replaced by `depth_m` over [t0, t1).
MissionLog withSurfaceReading(const MissionLog& in, double t0, double t1, double depth_m) {
  MissionLog out = in;
  LogChannel& z = *out.find("depth");
  for (std::size_t r = 0; r < out.rowCount(); ++r)
    if (out.time[r] >= t0 && out.time[r] < t1) z.values[r] = depth_m;
  return out;
}

// The log without its rows in [t0, t1): a logger drop-out.
MissionLog withDropOut(const MissionLog& in, double t0, double t1) {
  MissionLog out = in;
  const auto keep = [&](std::size_t r) { return in.time[r] < t0 || in.time[r] >= t1; };
  out.time.clear();
  for (LogChannel& c : out.channels) c.values.clear();
  for (std::size_t r = 0; r < in.rowCount(); ++r) {
    if (!keep(r)) continue;
    out.time.push_back(in.time[r]);
    for (std::size_t k = 0; k < in.channels.size(); ++k) out.channels[k].values.push_back(in.channels[k].values[r]);
  }
  return out;
}

TEST(TermReplayRestart, ASurfaceIntervalEndsTheReplayAndItStartsAgainFromTheLoggedStateAfterIt) {
  const Dive& d = dive();
  const MissionLog log = withSurfaceReading(d.log, 250.0, 320.0, 0.3);
  const sim::WaterColumn water = sim::waterColumnFromLog(log);
  TermReplayOptions o;
  o.surface_depth_m = 1.0;
  const TermReplayTrace tr = termReplay(d.vehicle.model, d.vehicle.autopilot, water, log, {}, log.time, o);
  const std::size_t inside = rowAt(log, 280.0), after = rowAt(log, 320.0);
  EXPECT_TRUE(std::isnan(tr.depth_m[inside])) << "the surface interval is not flown";
  EXPECT_NEAR(tr.since_start_s[after], 0.0, 1e-9);
  EXPECT_TRUE(std::isnan(tr.since_start_s[after - 1]));
  EXPECT_NEAR(tr.depth_m[after], log.channel("depth").values[after], 1e-9) << "restarts at the logged depth";
  EXPECT_NEAR(tr.since_start_s[rowAt(log, 240.0)], 240.0 - log.time.front(), 0.5) << "the first span runs from the start";

  // A dip above the limit shorter than a drop-out (30 s) is flown through.
  const MissionLog shortDip = withSurfaceReading(d.log, 250.0, 260.0, 0.3);
  const TermReplayTrace t2 = termReplay(d.vehicle.model, d.vehicle.autopilot, water, shortDip, {}, shortDip.time, o);
  EXPECT_NEAR(t2.since_start_s[rowAt(shortDip, 300.0)], 300.0 - shortDip.time.front(), 0.5);

  // Without a limit (the default) nothing is a surface interval.
  const TermReplayTrace t3 = termReplay(d.vehicle.model, d.vehicle.autopilot, water, log, {}, log.time, TermReplayOptions{});
  EXPECT_FALSE(std::isnan(t3.depth_m[inside]));
}

TEST(TermReplayRestart, ARestartMidClimbStartsWithTheLoggedDepthRate) {
  const Dive& d = dive();
  // The 30 -> 9 m leg starts at 400 s; the logger drops out from 350 s and
  // comes back at 405 s, with the vehicle climbing at 0.4 m/s.
  const MissionLog log = withDropOut(d.log, 350.0, 405.0);
  const std::vector<double>& z = log.channel("depth").values;
  const std::size_t r0 = rowAt(log, 405.0), r5 = rowAt(log, 410.0), r10 = rowAt(log, 415.0);
  const double loggedRate = (z[r5] - z[r0]) / (log.time[r5] - log.time[r0]);
  ASSERT_LT(loggedRate, -0.3) << "the test needs a climb";
  const sim::WaterColumn water = sim::waterColumnFromLog(d.log);
  const TermReplayTrace tr = termReplay(d.vehicle.model, d.vehicle.autopilot, water, log, {}, log.time, TermReplayOptions{});
  ASSERT_NEAR(tr.since_start_s[r0], 0.0, 1e-9) << "the drop-out restarts the replay";
  EXPECT_NEAR(-tr.vertical_velocity_mps[r0], loggedRate, 0.03);
  EXPECT_NEAR(tr.depth_m[r5], z[r5], 0.1);  // measured 0.07 m
  EXPECT_NEAR(tr.depth_m[r10], z[r10], 0.1);

  // The same log with the depth held for 5 s after the drop-out: the replay
  // restarts at rest in heave and lags the climb by its first seconds' travel.
  MissionLog still = log;
  std::vector<double>& zs = still.find("depth")->values;
  for (std::size_t r = r0 + 1; r <= r5; ++r) zs[r] = zs[r0];
  const TermReplayTrace rest = termReplay(d.vehicle.model, d.vehicle.autopilot, water, still, {}, still.time, TermReplayOptions{});
  EXPECT_NEAR(rest.vertical_velocity_mps[r0], 0.0, 0.05);
  EXPECT_GT(rest.depth_m[r10] - z[r10], 0.25);  // measured 0.39 m
}

// A Delphin2 3 kg too buoyant on a slow leg: the thrusters and planes cannot
// hold it down.
MissionLog buoyantLog(bool surface_model) {
  const Dive& d = dive();
  SyntheticAuvTruth t;
  t.ballast_error.net_buoyancy_kg = 3.0;
  SyntheticAuvMission m;
  m.legs_count = 2;
  m.leg_s = 300.0;
  m.depths_m = {5.0, 5.0};
  m.prop_demands = {14.0, 14.0};
  m.seed = 3;
  m.surface_model = surface_model;
  return synthesizeAuvLog(d.vehicle, "delphin2", t, m);
}

double minOf(const std::vector<double>& v) {
  double m = 1e300;
  for (double x : v)
    if (std::isfinite(x)) m = std::min(m, x);
  return m;
}

TEST(TermReplayRestart, ATooBuoyantVehicleFloatsAtTheSurfaceInTheTruthAndInTheReplay) {
  const MissionLog sky = buoyantLog(false), sea = buoyantLog(true);
  ASSERT_LT(minOf(sky.channel("depth").values), -3.0) << "the test needs a vehicle that cannot stay down";
  EXPECT_GT(minOf(sea.channel("depth").values), -0.3) << "with the surface model it floats";
  const Dive& d = dive();
  const sim::WaterColumn water = sim::waterColumnFromLog(sea);
  TermReplayOptions o;
  o.loading.error.net_buoyancy_kg = 3.0;
  o.surface_model = true;
  const TermReplayTrace tr = termReplay(d.vehicle.model, d.vehicle.autopilot, water, sea, {}, sea.time, o);
  EXPECT_GT(minOf(tr.depth_m), -0.3);
  o.surface_model = false;
  const TermReplayTrace noSurface = termReplay(d.vehicle.model, d.vehicle.autopilot, water, sea, {}, sea.time, o);
  EXPECT_LT(minOf(noSurface.depth_m), -3.0) << "without it the replay climbs on out of the water";
}

}  // namespace
}  // namespace auv::discrepancy
