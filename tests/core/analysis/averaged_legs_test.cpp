// Legs flown in a slow oscillation (averaged_legs.h): found, cut to whole
// cycles, averaged with an honest standard error; steady legs keep their
// steady windows; a data gap ends a leg.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/averaged_legs.h"
#include "analysis/segments.h"
#include "analysis/series_tools.h"
#include "analysis/steady_segment_json.h"
#include "common/input_error.h"
#include "log_builder.h"

namespace auv::analysis {
namespace {

using test::fill;
using test::makeLog;

constexpr double kPeriod_s = 420.0;
constexpr double kPitch0_deg = -0.8, kPitchAmp_deg = 6.0;
constexpr double kElev0_deg = -3.0, kElevAmp_deg = 9.0;

// One 2 h leg at 40 m and 150 rpm; `amp` scales the oscillation (0 = steady).
MissionLog legLog(double amp, std::uint32_t seed = 7) {
  MissionLog log = makeLog(0.0, 7200.0, 1.0);
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01;
  const double w = 2.0 * std::numbers::pi / kPeriod_s;
  fill(log, "depth_cmd", "m", [](std::size_t, double) { return 40.0; });
  // The depth lags the pitch by a quarter cycle (it integrates the climb rate).
  fill(log, "depth", "m", [&](std::size_t, double t) { return 40.0 - amp * 0.8 * std::cos(w * t) + 0.02 * n01(rng); });
  fill(log, "pitch", "deg", [&](std::size_t, double t) { return kPitch0_deg + amp * kPitchAmp_deg * std::sin(w * t) + 0.05 * n01(rng); });
  fill(log, "elevator", "deg", [&](std::size_t, double t) { return kElev0_deg + amp * kElevAmp_deg * std::sin(w * t + 0.7) + 0.1 * n01(rng); });
  fill(log, "speed", "m/s", [&](std::size_t, double) { return 1.8 + 0.01 * n01(rng); });
  fill(log, "prop_rpm", "rpm", [](std::size_t, double) { return 150.0; });
  fill(log, "roll", "deg", [&](std::size_t, double) { return 1.0 + 0.05 * n01(rng); });
  return log;
}

TEST(AveragedLegs, AnOscillatingLegIsAveragedOverWholeCycles) {
  const MissionLog log = legLog(1.0);
  const Segmentation seg = detectSegments(log, SegmentOptions{});
  ASSERT_EQ(seg.operating.size(), 1u) << "one averaged leg, no steady windows inside it";
  const Segment& leg = seg.operating.front();
  ASSERT_TRUE(leg.averaged());
  const std::size_t cycles = leg.cycle_bounds_s.size() - 1;
  EXPECT_GE(cycles, 12u);  // ~16 periods in the leg, minus settling
  // Each cycle is one period of the oscillation (boundaries found to a few seconds).
  for (std::size_t k = 0; k < cycles; ++k)
    EXPECT_NEAR(leg.cycle_bounds_s[k + 1] - leg.cycle_bounds_s[k], kPeriod_s, 15.0) << "cycle " << k;
  // The mean over whole cycles is the oscillation's centre; a plain mean over
  // the leg would carry up to amp / (2 pi cycles) of a partial cycle.
  const MeanEstimate p = cycleMean(log.series("pitch"), leg.cycle_bounds_s);
  const MeanEstimate e = cycleMean(log.series("elevator"), leg.cycle_bounds_s);
  EXPECT_NEAR(p.mean, kPitch0_deg, 0.05);
  EXPECT_NEAR(e.mean, kElev0_deg, 0.08);
  // The stated error covers the true one and is far below the swing.
  EXPECT_GT(p.se, std::abs(p.mean - kPitch0_deg) / 3.0);
  EXPECT_LT(p.se, 0.1);
  bool noted = false;
  for (const Message& m : seg.notes) noted = noted || m.id() == "analysis.averaged_legs";
  EXPECT_TRUE(noted);
}

TEST(AveragedLegs, TheCycleMeansOfTheBalanceProductsAreNotTheProductsOfTheMeans) {
  const MissionLog log = legLog(1.0);
  const Segment leg = detectSegments(log, SegmentOptions{}).operating.front();
  ASSERT_TRUE(leg.averaged());
  const TimeSeries depth = log.series("depth");
  const TimeSeries rate{depth.t, std::vector<double>(depth.size(), 0.0)};  // w from the pitch alone
  const auto r = cycleRegressors(log, rate, leg.cycle_bounds_s);
  ASSERT_TRUE(r.has_value());
  // Oracle: w = u tan(theta) / cos(phi) over one period of the sinusoid, by quadrature.
  const double u = 1.8, d2r = std::numbers::pi / 180.0;
  double au_u_e = 0.0, u_w = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double ph = 2.0 * std::numbers::pi * (i + 0.5) / n;
    const double th = (kPitch0_deg + kPitchAmp_deg * std::sin(ph)) * d2r;
    u_w += u * u * std::tan(th) / std::cos(1.0 * d2r) / n;
    au_u_e += u * u * (kElev0_deg + kElevAmp_deg * std::sin(ph + 0.7)) / n;
  }
  EXPECT_NEAR(r->u_w, u_w, 0.003 * std::abs(u_w) + 2e-4);
  EXPECT_NEAR(r->au_u_e, au_u_e, 0.02 * std::abs(au_u_e));
  // |w| w of a swing about a small mean is far from |w_mean| w_mean.
  const double w_mean = u * std::tan(kPitch0_deg * d2r);
  EXPECT_GT(std::abs(r->aw_w - std::abs(w_mean) * w_mean), 2.0 * std::abs(w_mean) * std::abs(w_mean));
}

// A fast limit cycle (truth 1145 of the identification bench: 18.5 s, pitch
// +-12 deg at 148 rpm): the angle of attack swings a little while u sin(theta)
// and the climb rate swing a lot and cancel. The cycle products must take the
// climb rate that follows the cycle; the means' 20 s rate flattens it, and
// |w| w then carries the whole u sin(theta) swing (there: 1.7 kg of net
// buoyancy read into cross-flow lift).
TEST(AveragedLegs, TheCycleProductsFollowTheAngleOfAttackThroughAFastLimitCycle) {
  constexpr double period_s = 18.5, u = 1.8, d2r = std::numbers::pi / 180.0;
  constexpr double th0 = -2.0 * d2r, th_amp = 12.0 * d2r, w0 = -0.055, w_amp = 0.08, w_lead = 1.1;
  const double om = 2.0 * std::numbers::pi / period_s;
  auto theta = [&](double t) { return th0 + th_amp * std::sin(om * t); };
  auto wOf = [&](double t) { return w0 + w_amp * std::sin(om * t + w_lead); };
  // Depth from the kinematics z_dot = -u sin(theta) + w cos(theta), integrated finely.
  MissionLog log = makeLog(0.0, 40.0 * period_s, 1.0);
  std::vector<double> depth(log.time.size());
  double z = 30.0, t = 0.0;
  constexpr double dt = 1e-3;
  for (std::size_t i = 0; i < log.time.size(); ++i) {
    for (; t < log.time[i] - 0.5 * dt; t += dt) {
      const double tm = t + 0.5 * dt;
      z += dt * (-u * std::sin(theta(tm)) + wOf(tm) * std::cos(theta(tm)));
    }
    depth[i] = z;
  }
  std::mt19937 rng(11);
  std::normal_distribution<double> n01;
  fill(log, "depth", "m", [&](std::size_t i, double) { return depth[i] + 0.01 * n01(rng); });
  fill(log, "pitch", "deg", [&](std::size_t, double tt) { return theta(tt) / d2r + 0.05 * n01(rng); });
  fill(log, "speed", "m/s", [&](std::size_t, double) { return u; });
  fill(log, "elevator", "deg", [&](std::size_t, double) { return -2.0; });
  std::vector<double> bounds;
  for (int k = 2; k <= 38; ++k) bounds.push_back(k * period_s);
  // Oracle: the mean of |w| w over one period by quadrature.
  double aw_w = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double w = wOf((i + 0.5) * period_s / n);
    aw_w += std::abs(w) * w / n;
  }
  const TimeSeries d = log.series("depth");
  const SegmentOptions o;
  const auto fast = cycleRegressors(log, {d.t, localRate(d, o.cycle_rate_window_s, o.max_gap_s)}, bounds);
  const auto slow = cycleRegressors(log, {d.t, localRate(d, o.rate_window_s, o.max_gap_s)}, bounds);
  ASSERT_TRUE(fast && slow);
  EXPECT_NEAR(fast->aw_w, aw_w, 0.15 * std::abs(aw_w)) << "oracle " << aw_w;
  EXPECT_NEAR(fast->u_w, u * w0, 0.05 * std::abs(u * w0));
  // The control: the means' rate reads the swing of u sin(theta) as angle of attack.
  EXPECT_GT(std::abs(slow->aw_w - aw_w), 1.0 * std::abs(aw_w)) << "slow " << slow->aw_w << " oracle " << aw_w;
}

TEST(AveragedLegs, ASteadyLegKeepsItsSteadyWindows) {
  const MissionLog log = legLog(0.0);
  const Segmentation seg = detectSegments(log, SegmentOptions{});
  ASSERT_FALSE(seg.operating.empty());
  for (const Segment& s : seg.operating) EXPECT_FALSE(s.averaged());
}

TEST(AveragedLegs, ADataGapEndsTheLeg) {
  MissionLog log = legLog(1.0);
  // Drop 10 min in the middle of the leg: the rows are gone, as in a real drop-out.
  MissionLog cut;
  cut.metadata = log.metadata;
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < log.time.size(); ++i)
    if (log.time[i] < 3000.0 || log.time[i] > 3600.0) keep.push_back(i);
  for (std::size_t i : keep) cut.time.push_back(log.time[i]);
  for (const LogChannel& c : log.channels) {
    LogChannel& d = cut.addChannel(c.name, c.unit);
    for (std::size_t j = 0; j < keep.size(); ++j) d.values[j] = c.values[keep[j]];
  }
  const Segmentation seg = detectSegments(cut, SegmentOptions{});
  ASSERT_GE(seg.operating.size(), 2u);
  for (const Segment& s : seg.operating) {
    EXPECT_TRUE(s.averaged());
    EXPECT_FALSE(s.start_s < 3000.0 && s.end_s > 3600.0) << s.start_s << " .. " << s.end_s;
  }
}

// A vehicle that cannot hold its depth: 20 min sinking at a steady -12 deg
// with the elevator at its stop, constant commands.
TEST(AveragedLegs, ASteadySinkIsAGlideOutsideTheErrorsAtDepth) {
  MissionLog log = makeLog(0.0, 3000.0, 1.0);
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  auto depth = [](double t) { return t < 600.0 ? 40.0 : 40.0 + 0.35 * (t - 600.0); };
  fill(log, "depth_cmd", "m", [](std::size_t, double) { return 40.0; });
  fill(log, "depth", "m", [&](std::size_t, double t) { return depth(t) + 0.02 * n01(rng); });
  fill(log, "pitch", "deg", [&](std::size_t, double t) { return (t < 600.0 ? 0.5 : -12.0) + 0.05 * n01(rng); });
  fill(log, "elevator", "deg", [&](std::size_t, double t) { return (t < 600.0 ? -3.0 : 25.0) + 0.1 * n01(rng); });
  fill(log, "speed", "m/s", [&](std::size_t, double) { return 1.6 + 0.01 * n01(rng); });
  fill(log, "prop_rpm", "rpm", [](std::size_t, double) { return 130.0; });
  const Segmentation seg = detectSegments(log, SegmentOptions{});
  const Segment* glide = nullptr;
  for (const Segment& s : seg.operating)
    if (s.kind == SegmentKind::kGlide) glide = &s;
  ASSERT_NE(glide, nullptr);
  EXPECT_EQ(glide->phase, SegmentKind::kDive);
  EXPECT_GE(glide->duration(), 2000.0);
  EXPECT_GE(glide->start_s, 600.0);
  // Switched off, the sink is not used.
  SegmentOptions off;
  off.auv_steady_glides = false;
  for (const Segment& s : detectSegments(log, off).operating) EXPECT_NE(s.kind, SegmentKind::kGlide);
}

// A survey's depth change: the depth command steps from 26 to 78 m and the
// propeller from 150 to 180 rpm at t = 600 s; the vehicle pitches down to
// its -15 deg limit within 15 s, holds it for 80 s, and levels off. The
// plateau, less 10 s at each end, is a steady dive. The settling time
// after the rpm change used to cut it to 31 s and lose it.
TEST(AveragedLegs, ThePitchLimitedMiddleOfADepthChangeIsAGlide) {
  MissionLog log = makeLog(0.0, 1800.0, 1.0);
  std::mt19937 rng(5);
  std::normal_distribution<double> n01;
  auto pitch = [](double t) {
    if (t < 600.0) return 0.8;
    if (t < 615.0) return 0.8 - 15.8 * (t - 600.0) / 15.0;
    if (t < 695.0) return -15.0;
    if (t < 715.0) return -15.0 + 15.8 * (t - 695.0) / 20.0;
    return 0.8;
  };
  auto depth = [](double t) {  // 0.55 m/s down on the plateau, ramps at both ends
    if (t < 605.0) return 26.0;
    if (t < 725.0) return 26.0 + 52.0 * (t - 605.0) / 120.0;
    return 78.0;
  };
  fill(log, "depth_cmd", "m", [](std::size_t, double t) { return t < 600.0 ? 26.0 : 78.0; });
  fill(log, "depth", "m", [&](std::size_t, double t) { return depth(t) + 0.02 * n01(rng); });
  fill(log, "pitch", "deg", [&](std::size_t, double t) { return pitch(t) + 0.05 * n01(rng); });
  fill(log, "elevator", "deg", [&](std::size_t, double t) { return (t < 600.0 || t > 715.0 ? -9.0 : -4.8) + 0.1 * n01(rng); });
  fill(log, "speed", "m/s", [&](std::size_t, double t) { return (t < 600.0 ? 1.85 : 2.2) + 0.01 * n01(rng); });
  fill(log, "prop_rpm", "rpm", [](std::size_t, double t) { return t < 600.0 ? 150.0 : std::min(180.0, 150.0 + 2.5 * (t - 600.0)); });
  const Segmentation seg = detectSegments(log, SegmentOptions{});
  std::vector<Segment> glides;
  for (const Segment& s : seg.operating)
    if (s.kind == SegmentKind::kGlide) glides.push_back(s);
  ASSERT_EQ(glides.size(), 1u);
  EXPECT_EQ(glides[0].phase, SegmentKind::kDive);
  // The plateau is [615, 695] (less the 6 s smoothing at its edges), then 10 s off each end.
  EXPECT_NEAR(glides[0].start_s, 625.0, 4.0);
  EXPECT_NEAR(glides[0].end_s, 685.0, 4.0);
}

TEST(AveragedLegs, HistoryRowsKeepTheCycleMeans) {
  SteadySegmentMeans s;
  s.start_s = 100.0;
  s.end_s = 2000.0;
  s.speed_mps.mean = 1.8;
  s.speed_mps.n = 1900;
  s.regressors = BalanceRegressors{0.99, -0.014, -0.05, -0.05, 0.031, 3.24, -9.7};
  s.pressure_dbar = 61.5;  // the hull law's levers of a history segment
  s.temperature_degC = 8.25;
  const nlohmann::json j = steadySegmentsJson({s, SteadySegmentMeans{}});
  const std::vector<SteadySegmentMeans> back = steadySegmentsFromJson(j, "history.segments");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_DOUBLE_EQ(back[0].pressure_dbar, 61.5);
  EXPECT_DOUBLE_EQ(back[0].temperature_degC, 8.25);
  EXPECT_TRUE(std::isnan(back[1].pressure_dbar));  // rows written without them: no lever
  ASSERT_TRUE(back[0].regressors.has_value());
  EXPECT_DOUBLE_EQ(back[0].regressors->aw_w, 0.031);
  EXPECT_DOUBLE_EQ(back[0].regressors->au_u_e, -9.7);
  EXPECT_FALSE(back[1].regressors.has_value());
  nlohmann::json bad = j;
  bad[0]["cycle_regressors"]["u_w"] = "x";
  try {
    steadySegmentsFromJson(bad, "history.segments");
    FAIL() << "a damaged cycle mean was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("history.segments[0].cycle_regressors.u_w"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace auv::analysis
