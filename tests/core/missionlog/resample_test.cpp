#include "missionlog/resample.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.h"

namespace auv {
namespace {
const double kNaN = std::nan("");

// Two sensors on one row time base: depth every row except a 30 s hole, a
// command written only when it changes.
MissionLog sampleLog() {
  MissionLog log;
  for (int i = 0; i <= 100; ++i) log.time.push_back(i * 1.0);
  LogChannel& depth = log.addChannel("depth", "m");
  LogChannel& cmd = log.addChannel("depth_cmd", "m");
  for (int i = 0; i <= 100; ++i) {
    if (i < 40 || i > 69) depth.values[i] = 2.0 + 0.5 * i;  // linear: interpolation is exact
  }
  cmd.values[0] = 10.0;
  cmd.values[50] = 20.0;
  return log;
}
}  // namespace

TEST(Resample, SeriesIsTheChannelsOwnTimeBase) {
  const MissionLog log = sampleLog();
  const TimeSeries d = log.series("depth");
  EXPECT_EQ(d.size(), 71u);  // 40 + 31
  EXPECT_EQ(log.channel("depth").validCount(), 71u);
  EXPECT_DOUBLE_EQ(d.t[39], 39.0);
  EXPECT_DOUBLE_EQ(d.t[40], 70.0);
  EXPECT_EQ(log.validTimes("depth_cmd"), (std::vector<double>{0.0, 50.0}));
  EXPECT_THROW(log.series("altitude"), InputError);
}

TEST(Resample, LinearIsExactOnALineAndRefusesLongHoles) {
  const MissionLog log = sampleLog();
  const TimeSeries d = log.series("depth");
  const std::vector<double> at = {0.25, 10.5, 38.5, 39.5, 69.9, 70.0, 100.0, 100.5, -1.0};
  ResampleOptions o;
  o.max_gap_s = 5.0;
  const auto v = resample(d, at, o);
  EXPECT_DOUBLE_EQ(v[0], 2.125);
  EXPECT_DOUBLE_EQ(v[1], 7.25);
  EXPECT_DOUBLE_EQ(v[2], 21.25);
  EXPECT_TRUE(std::isnan(v[3]));  // inside the 31 s hole (39 .. 70 s)
  EXPECT_TRUE(std::isnan(v[4]));
  EXPECT_DOUBLE_EQ(v[5], 37.0);  // exactly on a sample
  EXPECT_DOUBLE_EQ(v[6], 52.0);
  EXPECT_TRUE(std::isnan(v[7]));  // no extrapolation
  EXPECT_TRUE(std::isnan(v[8]));
  // Without a gap limit the hole is bridged by the straight line 2 + 0.5 t.
  const auto bridged = resample(d, std::vector<double>{55.0});
  EXPECT_DOUBLE_EQ(bridged[0], 29.5);
}

TEST(Resample, HoldKeepsCommandsUntilTheNextOne) {
  const MissionLog log = sampleLog();
  ResampleOptions hold;
  hold.method = Interpolation::kHold;
  const auto v = resample(log.series("depth_cmd"), std::vector<double>{0.0, 49.9, 50.0, 99.0, -0.5}, hold);
  EXPECT_DOUBLE_EQ(v[0], 10.0);
  EXPECT_DOUBLE_EQ(v[1], 10.0);
  EXPECT_DOUBLE_EQ(v[2], 20.0);
  EXPECT_DOUBLE_EQ(v[3], 20.0);
  EXPECT_TRUE(std::isnan(v[4]));
  hold.max_gap_s = 30.0;  // a command older than 30 s is no longer trusted
  const auto limited = resample(log.series("depth_cmd"), std::vector<double>{29.0, 31.0, 79.0, 81.0}, hold);
  EXPECT_DOUBLE_EQ(limited[0], 10.0);
  EXPECT_TRUE(std::isnan(limited[1]));
  EXPECT_DOUBLE_EQ(limited[2], 20.0);
  EXPECT_TRUE(std::isnan(limited[3]));
}

TEST(Resample, AlignToAnotherChannelAndUniformGrid) {
  const MissionLog log = sampleLog();
  ResampleOptions hold;
  hold.method = Interpolation::kHold;
  const TimeSeries a = alignTo(log, "depth_cmd", "depth", hold);
  ASSERT_EQ(a.size(), 71u);
  EXPECT_DOUBLE_EQ(a.v[0], 10.0);
  EXPECT_DOUBLE_EQ(a.v[40], 20.0);  // t = 70

  const auto g = uniformGrid(0.0, 1.0, 0.1);
  ASSERT_EQ(g.size(), 11u);  // 1.0 is included despite 10 * 0.1 != 1.0 in binary
  EXPECT_DOUBLE_EQ(g[3], 0.30000000000000004);
  EXPECT_THROW(uniformGrid(0.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_TRUE(uniformGrid(1.0, 0.0, 0.1).empty());

  ResampleOptions lin;
  lin.max_gap_s = 2.0;
  const TimeSeries u = resampleUniform(log, "depth", 0.5, lin);
  ASSERT_EQ(u.size(), 201u);
  EXPECT_DOUBLE_EQ(u.v[1], 2.25);
  EXPECT_TRUE(std::isnan(u.v[100]));  // t = 50, in the hole
}

}  // namespace auv
