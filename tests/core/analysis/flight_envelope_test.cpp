// Legs not flown as commanded (flight_envelope.h): a vehicle stuck above or
// below its command with the elevator at a stop, and a porpoising one, are
// found with their numbers; a steady leg, a slow oscillation the analysis
// averages and a followed depth step are not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "analysis/flight_envelope.h"
#include "analysis/mission_analysis.h"
#include "analysis/segments.h"
#include "log_builder.h"

namespace auv::analysis {
namespace {

using test::fill;
using test::makeLog;

// One hour at 150 rpm commanded to 40 m. depth(t), pitch(t) and the
// elevator demand(t) are given; the elevator is clipped at +-stop.
MissionLog hourLog(const std::function<double(double)>& depth, const std::function<double(double)>& pitch,
                   const std::function<double(double)>& demand, double stop_deg = 25.0,
                   const std::function<double(double)>& cmd = [](double) { return 40.0; }) {
  MissionLog log = makeLog(0.0, 3600.0, 1.0);
  std::mt19937 rng(11);
  std::normal_distribution<double> n01;
  fill(log, "depth_cmd", "m", [&](std::size_t, double t) { return cmd(t); });
  fill(log, "depth", "m", [&](std::size_t, double t) { return depth(t) + 0.02 * n01(rng); });
  fill(log, "pitch", "deg", [&](std::size_t, double t) { return pitch(t) + 0.05 * n01(rng); });
  fill(log, "elevator", "deg", [&](std::size_t, double t) { return std::clamp(demand(t) + 0.1 * n01(rng), -stop_deg, stop_deg); });
  fill(log, "speed", "m/s", [&](std::size_t, double) { return 1.8 + 0.01 * n01(rng); });
  fill(log, "prop_rpm", "rpm", [](std::size_t, double) { return 150.0; });
  return log;
}

FlightEnvelope envelopeOf(const MissionLog& log) {
  const SegmentOptions o;
  const Segmentation seg = detectSegments(log, o);
  return flightEnvelope(log, log.series("depth"), seg.command_cuts, seg.operating, o);
}

TEST(FlightEnvelope, AVehicleThatNeverLeavesTheSurfaceWithTheElevatorAtItsStopIsTooLight) {
  // Nose up at the surface, the elevator pinned at its dive stop.
  const MissionLog log = hourLog([](double) { return 0.4; }, [](double) { return 8.0; }, [](double) { return 40.0; });
  const FlightEnvelope e = envelopeOf(log);
  ASSERT_TRUE(e.too_light.has_value());
  EXPECT_FALSE(e.too_heavy.has_value());
  EXPECT_FALSE(e.porpoising.has_value());
  EXPECT_EQ(e.too_light->legs, 1);
  EXPECT_NEAR(e.too_light->seconds, 3600.0 - EnvelopeOptions{}.settle_s, 1.0);
  EXPECT_NEAR(e.too_light->depth_error_m, 0.4 - 40.0, 0.05);
  EXPECT_NEAR(e.too_light->elevator_stop_deg, 25.0, 0.01);
}

TEST(FlightEnvelope, AVehicleBelowItsCommandWithTheElevatorAtTheOtherStopIsTooHeavy) {
  // Sinking from 40 to 100 m nose down, the elevator at its climb stop (-20 deg).
  const MissionLog log = hourLog([](double t) { return 40.0 + 60.0 * t / 3600.0; }, [](double) { return -6.0; },
                                 [](double) { return -35.0; }, 20.0);
  const FlightEnvelope e = envelopeOf(log);
  ASSERT_TRUE(e.too_heavy.has_value());
  EXPECT_FALSE(e.too_light.has_value());
  EXPECT_NEAR(e.too_heavy->elevator_stop_deg, 20.0, 0.01);
  // Median depth error over [120 s, 3600 s]: 60 m * 1860 / 3600.
  EXPECT_NEAR(e.too_heavy->depth_error_m, 60.0 * 1860.0 / 3600.0, 0.2);
}

TEST(FlightEnvelope, APorpoisingLegIsFoundWithItsSwingAndPeriod) {
  constexpr double kPeriod_s = 24.0;
  const double w = 2.0 * std::numbers::pi / kPeriod_s;
  // Pitch +-30 deg every 24 s about the command's depth; the elevator's
  // demand swings +-30 deg and clips at 25 (38 % of the time: not "at the stop").
  const MissionLog log = hourLog([&](double t) { return 40.0 - 3.0 * std::cos(w * t); },
                                 [&](double t) { return 30.0 * std::sin(w * t); },
                                 [&](double t) { return -30.0 * std::sin(w * t + 0.5); });
  const FlightEnvelope e = envelopeOf(log);
  ASSERT_TRUE(e.porpoising.has_value());
  EXPECT_FALSE(e.too_light.has_value());
  EXPECT_FALSE(e.too_heavy.has_value());
  EXPECT_EQ(e.porpoising->legs, 1);
  EXPECT_NEAR(e.porpoising->period_s, kPeriod_s, 0.5);
  EXPECT_NEAR(e.porpoising->pitch_sd_deg, 30.0 / std::sqrt(2.0), 0.3);
}

TEST(FlightEnvelope, SteadyFlightAFollowedDepthStepAndASlowAveragedSwingAreNotFlagged) {
  // Steady at the command, the elevator trimming at -3 deg (its extreme is no clip).
  const MissionLog steady = hourLog([](double) { return 40.0; }, [](double) { return -0.8; }, [](double) { return -3.0; });
  const FlightEnvelope a = envelopeOf(steady);
  EXPECT_FALSE(a.too_light || a.too_heavy || a.porpoising);
  EXPECT_GT(a.leg_seconds, 3000.0);
  // A depth step at 1800 s followed within 90 s with the elevator briefly at its stop.
  const MissionLog step = hourLog([](double t) { return t < 1800 ? 40.0 : t < 1890 ? 40.0 + 20.0 * (t - 1800) / 90.0 : 60.0; },
                                  [](double t) { return t >= 1800 && t < 1890 ? -15.0 : -0.8; },
                                  [](double t) { return t >= 1800 && t < 1890 ? 40.0 : -3.0; }, 25.0,
                                  [](double t) { return t < 1800 ? 40.0 : 60.0; });
  const FlightEnvelope b = envelopeOf(step);
  EXPECT_FALSE(b.too_light || b.too_heavy || b.porpoising);
  // A slow swing (7-min period, +-6 deg) about the command: averaged over cycles, not porpoising.
  const double w = 2.0 * std::numbers::pi / 420.0;
  const MissionLog slow = hourLog([&](double t) { return 40.0 - 0.8 * std::cos(w * t); },
                                  [&](double t) { return -0.8 + 6.0 * std::sin(w * t); },
                                  [&](double t) { return -3.0 + 9.0 * std::sin(w * t + 0.7); });
  const FlightEnvelope c = envelopeOf(slow);
  EXPECT_FALSE(c.too_light || c.too_heavy || c.porpoising);
}

}  // namespace
}  // namespace auv::analysis
