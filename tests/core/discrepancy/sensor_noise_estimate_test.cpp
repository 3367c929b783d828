// The sensor-noise estimate a noise twin flies with (discrepancy/
// sensor_noise_estimate.h), against noise of known sigma added to motion a
// vehicle makes at a 1 Hz row rate.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "discrepancy/sensor_noise_estimate.h"
#include "sim/sensor_noise.h"

namespace auv::discrepancy {
namespace {

MissionLog oscillatingLog(double pitch_sigma_deg, double depth_sigma_m) {
  MissionLog log;
  sim::GaussianSource g(42);
  LogChannel pitch{"pitch", "deg", "deg", {}}, depth{"depth", "m", "m", {}};
  for (int i = 0; i < 7200; ++i) {
    const double t = i;
    log.time.push_back(t);
    // A 20 s pitch oscillation of 1 deg over a 7 s one of 0.3 deg, a 2 m
    // depth step every 10 min on a climb: what a cubic over 5 rows follows.
    pitch.values.push_back(std::sin(2 * std::numbers::pi * t / 20) + 0.3 * std::sin(2 * std::numbers::pi * t / 7) +
                           g.next(pitch_sigma_deg));
    depth.values.push_back(30.0 + 2.0 * std::tanh((std::fmod(t, 600.0) - 300.0) / 20.0) + 0.01 * t + g.next(depth_sigma_m));
  }
  // Drop-outs and an irregular stretch are skipped, not read as noise.
  for (int i = 1000; i < 1040; ++i) pitch.values[i] = std::nan("");
  for (int i = 3000; i < 3100; ++i) log.time[i] += 0.4 * (i % 2);
  log.channels = {pitch, depth};
  return log;
}

TEST(SensorNoiseEstimate, RecoversTheSigmaUnderAVehiclesMotion) {
  for (const double sigma : {0.03, 0.08}) {
    const MissionLog log = oscillatingLog(sigma, 0.02);
    EXPECT_NEAR(estimateChannelNoise(log, "pitch"), sigma, 0.06 * sigma);
    EXPECT_NEAR(estimateChannelNoise(log, "depth"), 0.02, 0.06 * 0.02);
  }
}

TEST(SensorNoiseEstimate, AMissingChannelHasNone) {
  const MissionLog log = oscillatingLog(0.05, 0.02);
  EXPECT_EQ(estimateChannelNoise(log, "roll"), 0.0);
  const sim::SensorNoise n = estimateSensorNoise(log);
  EXPECT_NEAR(n.pitch_rad, 0.05 * std::numbers::pi / 180, 0.003 * std::numbers::pi / 180);
  EXPECT_EQ(n.roll_rad, 0.0);
  EXPECT_EQ(n.pitch_rate_radps, 0.0);  // not logged
}

}  // namespace
}  // namespace auv::discrepancy
