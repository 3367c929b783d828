// The thesis's App. D checks ('classic' mode) on a small reconstruction of
// its post-mission test (Table 7.1: depth error +8.76 m, pitch -0.60 deg,
// roll +0.74 deg: too light, nose down, starboard down), with hand-computed
// values, and what the exact-equality tests do to real, noisy data.
#include <gtest/gtest.h>

#include <random>

#include "analysis/classic_thesis.h"
#include "analysis/mission_analysis.h"
#include "log_builder.h"
#include "vehicle/vehicle_catalog.h"

using namespace auv;
using namespace auv::analysis;
using namespace auv::analysis::classic;
using auv::analysis::test::fill;
using auv::analysis::test::kNaN;
using auv::analysis::test::makeLog;

TEST(ClassicThesis, DepthComparisonSignAndWindow) {
  // Holding 0.5 m above a constant command: +0.5 (too light). Window is
  // samples 400..600 of 1000 (1-based), i.e. 201 samples.
  std::vector<double> cmd(1000, 100.0), meas(1000, 99.5);
  const ClassicValue v = depthComparison(cmd, meas);
  EXPECT_DOUBLE_EQ(v.value, 0.5);
  EXPECT_EQ(v.samples, 201u);
  for (double& m : meas) m = 100.3;  // too deep: heavy
  EXPECT_NEAR(depthComparison(cmd, meas).value, -0.3, 1e-12);
}

TEST(ClassicThesis, DepthComparisonZerosAfterAStepDiluteTheMean) {
  // Command 60 m, then 100 m from sample 451; the vehicle always 0.5 m short.
  // D.1 marks sample 451 NaN and jumps to 851, leaving 452..850 at 0. After
  // removing the NaN the window 400..600 holds 51 x 0.5 and 150 zeros:
  // 25.5 / 201 = 0.1269 instead of 0.5.
  std::vector<double> cmd(1000), meas(1000);
  for (std::size_t i = 0; i < 1000; ++i) {
    cmd[i] = i < 450 ? 60.0 : 100.0;
    meas[i] = cmd[i] - 0.5;
  }
  const ClassicValue v = depthComparison(cmd, meas);
  EXPECT_EQ(v.samples, 201u);
  EXPECT_NEAR(v.value, 25.5 / 201.0, 1e-12);
  EXPECT_FALSE(v.index_clamped);
}

TEST(ClassicThesis, PitchComparisonAndStableDepth) {
  std::vector<double> pitch(1000, -0.6), cmd(1000, 0.0);
  EXPECT_NEAR(pitchComparison(pitch, cmd).value, -0.6, 1e-12);  // Table 7.1: -0.59959
  // D.3 on a depth logged at 0.1 m resolution (repeats) vs with noise.
  std::vector<double> quantized(1000), noisy(1000);
  std::mt19937 rng(2);
  std::normal_distribution<double> n(0.0, 0.02);
  for (std::size_t i = 0; i < 1000; ++i) {
    quantized[i] = std::round((50.0 + n(rng)) * 10) / 10;
    noisy[i] = 50.0 + n(rng);
  }
  const ClassicValue q = pitchAtStableDepth(pitch, quantized);
  EXPECT_NEAR(q.value, -0.6, 1e-12);
  EXPECT_GT(q.samples, 100u);
  const ClassicValue z = pitchAtStableDepth(pitch, noisy);
  EXPECT_TRUE(std::isnan(z.value));  // no two equal depths: MATLAB's 0/0
  EXPECT_EQ(z.samples, 0u);
}

TEST(ClassicThesis, RollNeedsExactly160Rpm) {
  std::vector<double> roll(500, 0.74), rpm(500, 160.0), speed(500, 2.0);
  EXPECT_NEAR(rollAtCruise(roll, rpm, speed).value, 0.74, 1e-12);  // Table 7.1: +0.73636
  for (std::size_t i = 0; i < rpm.size(); ++i) rpm[i] = 160.0 + (i % 2 ? 0.25 : -0.25);
  EXPECT_TRUE(std::isnan(rollAtCruise(roll, rpm, speed).value));
  std::fill(rpm.begin(), rpm.end(), 160.0);
  std::fill(speed.begin(), speed.end(), 2.006);  // just outside 1.995 < v < 2.005
  EXPECT_TRUE(std::isnan(rollAtCruise(roll, rpm, speed).value));
}

namespace {

// A HUGIN-like mission with the thesis's error signs: depth command steps
// (50 -> 90 -> 60 m), the vehicle settles 0.3 m short of each command
// (first-order, 30 s), pitch -0.6 deg against a 0 deg command, roll +0.74
// deg at 160 rpm and 2 m/s. `noisy` adds sensor noise, including +-0.5 rpm.
MissionLog huginLikeMission(bool noisy) {
  MissionLog log = makeLog(0, 7200, 0.5);
  std::mt19937 rng(9);
  std::normal_distribution<double> n(0.0, 1.0);
  const double k = noisy ? 1.0 : 0.0;
  auto cmdAt = [](double t) { return t < 2400 ? 50.0 : (t < 4800 ? 90.0 : 60.0); };
  double z = 0.0, zc = 0.0;
  fill(log, "depth_cmd", "m", [&](std::size_t, double t) { return cmdAt(t); });
  fill(log, "depth", "m", [&](std::size_t, double t) {
    const double target = cmdAt(t) - 0.3;
    // Rate-limited approach (0.5 m/s), then first order.
    const double dz = target - zc;
    zc += std::clamp(dz * (1 - std::exp(-0.5 / 30.0)), -0.25, 0.25);
    if (t < 60) zc = 0.0;
    z = zc + k * 0.05 * n(rng);
    return z;
  });
  fill(log, "pitch_cmd", "deg", [](std::size_t, double) { return 0.0; });
  fill(log, "pitch", "deg", [&](std::size_t, double) { return -0.6 + k * 0.3 * n(rng); });
  fill(log, "roll", "deg", [&](std::size_t, double) { return 0.74 + k * 0.2 * n(rng); });
  fill(log, "prop_rpm", "rpm", [&](std::size_t, double) { return 160.0 + k * 0.5 * n(rng); });
  fill(log, "speed", "m/s", [&](std::size_t, double) { return 2.0 + k * 0.01 * n(rng); });
  return log;
}

}  // namespace

TEST(ClassicThesis, ReconstructedPostMissionCaseGivesTheThesisSigns) {
  const ClassicReport c = classicAnalysis(huginLikeMission(false));
  EXPECT_GT(c.depth_error_m.value, 0.0);   // Table 7.1: +8.7594 (too light)
  EXPECT_NEAR(c.pitch_error_deg.value, -0.6, 1e-12);  // -0.59959
  EXPECT_NEAR(c.roll_error_deg.value, 0.74, 1e-12);   // +0.73636
  EXPECT_EQ(c.roll_error_deg.samples, 14401u);
}

TEST(ClassicThesis, ToleranceBandsKeepWorkingWhereExactTestsFail) {
  const MissionLog log = huginLikeMission(true);
  const ClassicReport c = classicAnalysis(log);
  EXPECT_TRUE(std::isnan(c.roll_error_deg.value)) << "rpm is never exactly 160 in noisy data";
  EXPECT_TRUE(std::isnan(c.pitch_at_stable_depth_deg.value));
  const VehicleProfile hugin = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000");
  const AnalysisReport r = analyzeMission(log, hugin, {});
  // Same signs, the magnitudes of the truth, and intervals that exclude 0.
  EXPECT_NEAR(r.depth_error_m.mean, 0.3, 0.02);
  EXPECT_GT(r.depth_error_m.mean - r.depth_error_m.ci95, 0.0);
  EXPECT_NEAR(r.pitch_error_deg.mean, -0.6, 0.05);
  EXPECT_LT(r.pitch_error_deg.mean + r.pitch_error_deg.ci95, 0.0);
  EXPECT_NEAR(r.roll_deg.mean, 0.74, 0.05);
  EXPECT_GT(r.roll_deg.mean - r.roll_deg.ci95, 0.0);
  // Three steady legs (one per command), not a 40-60 % window; the depth
  // changes between them count as glides (kGlide), not as legs at depth.
  int legs = 0, glides = 0;
  for (const auto& s : r.segments) {
    legs += s.used && s.kind == SegmentKind::kSteady;
    glides += s.used && s.kind == SegmentKind::kGlide;
  }
  EXPECT_EQ(legs, 3);
  EXPECT_LE(glides, 3);
  // The classic numbers travel along in the report.
  EXPECT_TRUE(r.details["classic"]["roll_error_deg"]["value"].is_null());
  EXPECT_GT(r.details["classic"]["depth_error_m"]["value"].get<double>(), 0.0);
}
