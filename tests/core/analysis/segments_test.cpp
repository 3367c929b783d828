#include "analysis/segments.h"

#include <gtest/gtest.h>

#include <random>

#include "common/input_error.h"
#include "log_builder.h"

using namespace auv;
using namespace auv::analysis;
using auv::analysis::test::fill;
using auv::analysis::test::kNaN;
using auv::analysis::test::makeLog;

namespace {

// Piecewise-linear depth profile through (time, depth) knots.
double profile(const std::vector<std::pair<double, double>>& k, double t) {
  if (t <= k.front().first) return k.front().second;
  for (std::size_t i = 1; i < k.size(); ++i)
    if (t <= k[i].first)
      return k[i - 1].second + (t - k[i - 1].first) / (k[i].first - k[i - 1].first) * (k[i].second - k[i - 1].second);
  return k.back().second;
}

const std::vector<std::pair<double, double>> kAuvDive = {
    {0, 0.2}, {60, 0.2}, {160, 50}, {1000, 50}, {1060, 20}, {1700, 20}, {1740, 0.2}, {1800, 0.2}};

}  // namespace

TEST(Segments, AuvDiveLegsClimbsWithNoise) {
  MissionLog log = makeLog(0, 1800, 0.1);
  std::mt19937 rng(11);
  std::normal_distribution<double> n(0.0, 0.02);
  fill(log, "depth", "m", [&](std::size_t, double t) { return profile(kAuvDive, t) + n(rng); });
  const Segmentation s = detectSegments(log, {});
  ASSERT_EQ(s.phases.size(), 7u);
  const SegmentKind expect[] = {SegmentKind::kSurface, SegmentKind::kDive,  SegmentKind::kLevel, SegmentKind::kClimb,
                                SegmentKind::kLevel,   SegmentKind::kClimb, SegmentKind::kSurface};
  const double bounds[] = {0, 60, 160, 1000, 1060, 1700, 1740, 1800};
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(s.phases[i].kind, expect[i]) << i;
    // Boundaries within the 20 s rate window (the surface threshold sits
    // 1-1.5 m below the surface, i.e. 2-3 s into the dive).
    EXPECT_NEAR(s.phases[i].start_s, bounds[i], 12.0) << i;
    EXPECT_NEAR(s.phases[i].end_s, bounds[i + 1], 12.0) << i;
  }
  ASSERT_EQ(s.operating.size(), 2u);
  EXPECT_EQ(s.operating[0].kind, SegmentKind::kSteady);
  EXPECT_GE(s.operating[0].start_s, 160 + 30 - 12);
  EXPECT_LE(s.operating[0].end_s, 1000 + 12);
  EXPECT_GT(s.operating[0].duration(), 750);
  EXPECT_NEAR(s.max_depth_m, 50, 0.2);
}

TEST(Segments, CommandAndSpeedStepsSplitSteadyLegs) {
  MissionLog log = makeLog(0, 1800, 0.1);
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 0.01);
  fill(log, "depth", "m", [&](std::size_t, double t) { return profile(kAuvDive, t) + 3 * n(rng); });
  // Depth command: 50 m, then a 1 m nudge at 400 s (too small to show in the depth rate).
  fill(log, "depth_cmd", "m", [&](std::size_t i, double t) {
    if (i % 50) return kNaN;  // sparse, held
    return t < 400 ? 50.0 : (t < 1000 ? 51.0 : 20.0);
  });
  // Speed step 1.0 -> 1.5 m/s at 700 s, ramped over 5 s.
  fill(log, "speed", "m/s", [&](std::size_t, double t) {
    return (t < 700 ? 1.0 : t > 705 ? 1.5 : 1.0 + 0.1 * (t - 700)) + n(rng);
  });
  const Segmentation s = detectSegments(log, {});
  // First level leg [~190, 1000] is cut at 400 (+30 s settle) and at ~700 (+-10 s window, +30 s).
  ASSERT_EQ(s.operating.size(), 4u);
  EXPECT_NEAR(s.operating[0].end_s, 400, 1e-9);
  EXPECT_NEAR(s.operating[1].start_s, 430, 1e-9);
  EXPECT_NEAR(s.operating[1].end_s, 690, 12);
  EXPECT_NEAR(s.operating[2].start_s, 745, 12);
  EXPECT_FALSE(s.notes.empty());
}

TEST(Segments, GliderYosWithSparseDepthAndAGap) {
  // Yos 1 -> 40 m at 0.15 m/s, depth every 4 s, and a 10-minute data gap.
  MissionLog log = makeLog(0, 6000, 1.0);
  std::vector<std::pair<double, double>> k = {{0, 0.3}, {100, 0.3}};
  double t = 100;
  for (int yo = 0; yo < 6; ++yo) {
    t += 260;
    k.push_back({t, 40});
    t += 260;
    k.push_back({t, 1.5});
  }
  k.push_back({t + 40, 0.3});
  fill(log, "depth", "m", [&](std::size_t i, double tt) {
    if (i % 4) return kNaN;
    if (tt > 1500 && tt < 2100) return kNaN;
    return profile(k, tt);
  });
  SegmentOptions o;
  o.glider = true;
  const Segmentation s = detectSegments(log, o);
  int dives = 0, climbs = 0;
  for (const Segment& p : s.phases) {
    dives += p.kind == SegmentKind::kDive;
    climbs += p.kind == SegmentKind::kClimb;
  }
  // The gap (1500-2100 s) swallows the fourth dive (1664-1924 s) and cuts
  // the climbs on either side: 5 dives, 6 climbs.
  std::string trace;
  for (const Segment& p : s.phases)
    trace += std::string(toString(p.kind)) + " " + std::to_string(p.start_s) + "-" + std::to_string(p.end_s) + "\n";
  EXPECT_EQ(dives, 5) << trace;
  EXPECT_EQ(climbs, 6) << trace;
  // Leaving the surface at 1.5 m (surface threshold + hysteresis) at 0.15 m/s: 108 s.
  EXPECT_NEAR(s.phases[1].start_s, 108, 4.0);
  for (const Segment& g : s.operating) {
    EXPECT_EQ(g.kind, SegmentKind::kGlide);
    EXPECT_TRUE(g.phase == SegmentKind::kDive || g.phase == SegmentKind::kClimb);
    EXPECT_FALSE(g.start_s < 2100 && g.end_s > 1500) << "a glide spans the data gap";
  }
  // Every phase but the 80 s climb after the gap (too short once trimmed by 30 s at each end).
  EXPECT_EQ(s.operating.size(), 10u);
}

TEST(Segments, NoDepthIsAClearError) {
  MissionLog log = makeLog(0, 10, 1);
  fill(log, "pitch", "deg", [](std::size_t, double) { return 1.0; });
  try {
    detectSegments(log, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "depth");
    EXPECT_NE(std::string(e.what()).find("pressure"), std::string::npos);
  }
}

TEST(Segments, LocalRateOfALineIsItsSlope) {
  TimeSeries s;
  for (int i = 0; i < 500; ++i) {
    // Irregular sampling: the boxcar rate of a straight line is exact anyway.
    const double t = i * 0.7 + ((i % 3) ? 0.1 : 0.0);
    s.t.push_back(t);
    s.v.push_back(3.0 - 0.25 * t);
  }
  const std::vector<double> r = localRate(s, 10.0, 100.0);
  for (std::size_t i = 1; i + 1 < r.size(); ++i) EXPECT_NEAR(r[i], -0.25, 1e-9) << i;
  EXPECT_TRUE(std::isnan(r.front()));
}
