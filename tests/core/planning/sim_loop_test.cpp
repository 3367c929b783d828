// The closed loop with the simulator as truth and the real analysis (issue
// #6 item 5): mission -> analyze -> plan -> apply -> mission on HUGIN. The
// printed rates are those in docs/decisions/planning-closed-loop.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim_loop.h"

using namespace auv;
using namespace auv::closed_loop;

namespace {

constexpr int kCases = 30;
constexpr std::uint64_t kSeed = 2026;

struct Rates {
  int all = 0, net = 0, pitch = 0, roll = 0, depth = 0, safe = 0, n = 0;
  int reachable = 0, all_reachable = 0;  // cases whose static pitch band the kit can reach at all
  int static_pitch = 0;                  // static pitch (at rest) within the band, for the record
  int flight_predicted = 0;              // plans that predicted the flying pitch
  double flight_error_max = 0.0;         // |predicted - flown| flying pitch, deg
};

Rates run(const SimHarness& h, const char* label, bool show_misses = false) {
  Rates r;
  for (const SimLoopCase& c : makeSimCases(kCases, kSeed)) {
    const SimOutcome o = h.runOnce(c, PlanPolicy::Exact, true);
    r.all += o.spec.all(), r.net += o.spec.net, r.pitch += o.spec.pitch, r.roll += o.spec.roll;
    r.depth += o.spec.depth, r.safe += o.safe, ++r.n;
    r.reachable += o.reachable, r.all_reachable += o.reachable && o.spec.all();
    r.static_pitch += std::abs(o.after.pitch_deg) <= h.vehicle().spec.pitch_tolerance_deg;
    if (o.predicted_flight_pitch_deg) {
      ++r.flight_predicted;
      r.flight_error_max = std::max(r.flight_error_max, std::abs(*o.predicted_flight_pitch_deg - o.after.cruise_pitch_deg));
    }
    if (show_misses && !o.spec.all()) {
      std::printf("    miss: light %.2f kg, x %+.1f mm, y %+.2f mm -> net %.3f kg (est. sigma %.3f), flight pitch %+.2f deg, "
                  "(best %+.2f), cruise roll %+.3f deg (best %+.3f), depth %+.3f m\n",
                  c.light_kg, c.x_mm, c.y_mm, o.after.net_kg, o.before.report.value("net_buoyancy_sigma_kg", 0.0),
                  o.after.flight_pitch_deg, o.best_pitch_deg, o.after.cruise_roll_deg, o.best_roll_deg, o.after.depth_error_m);
      std::printf("      before: net %.3f est %.3f; planned net %.3f, static pitch %+.2f (after %+.2f), roll %+.3f\n",
                  o.before.net_kg, o.before.report.value("net_buoyancy_kg", 0.0), o.predicted_net_kg,
                  o.predicted_pitch_deg, o.after.pitch_deg, o.predicted_roll_deg);
      for (const auto& w : o.warnings) std::printf("      warning: %s\n", w.c_str());
    }
  }
  std::printf("  [sim, exact+0.5kg, %s] spec %d, net %d, flight pitch %d, cruise roll %d, depth %d, safe %d of %d "
              "(static pitch at rest in band: %d; flying pitch predicted in %d, worst error %.2f deg)\n",
              label, r.all, r.net, r.pitch, r.roll, r.depth, r.safe, r.n, r.static_pitch, r.flight_predicted,
              r.flight_error_max);
  return r;
}

}  // namespace

TEST(SimClosedLoop, OneIterationMeetsTheSpecWhenTheCoefficientsAreKnown) {
  // The target (>= 90 % after ONE move). The simulator flies exactly
  // the profile's hydrodynamic derivatives, so the analysis is told they are
  // known to 2 % (as after a tow-tank or model-check calibration); every
  // other sigma is the analysis's own. Pitch and roll are judged in flight
  // as the thesis measures them: pitch at steady depth, roll at cruise rpm.
  const SimHarness h({}, 0.02);
  const Rates r = run(h, "coefficients known to 2 %", true);
  EXPECT_EQ(r.safe, r.n);
  // The plan's flying pitch (analysis/level_flight.h at the last mission's
  // cruise speed) against the pitch the next mission flies at cruise rpm.
  EXPECT_EQ(r.flight_predicted, r.n);
  EXPECT_LT(r.flight_error_max, 0.1);
  EXPECT_EQ(r.depth, r.n);
  EXPECT_GE(r.all, (9 * r.n + 9) / 10);
}

TEST(SimClosedLoop, WithTenPercentCoefficientUncertaintyTheMoveStaysSafeAboveTheBand) {
  // With the default 10 % the analysis states 0.3-1.2 kg for net buoyancy
  // (a systematic error proportional to the lift carrying it: one move from
  // 8 kg light cannot promise a 1.2 kg band). The plan honours the stated
  // sigma: always safe, but the margin often lifts it above 1.2 kg.
  const SimHarness h;
  const Rates r = run(h, "coefficients known to 10 %");
  EXPECT_EQ(r.safe, r.n);
  EXPECT_EQ(r.depth, r.n);
  EXPECT_LT(r.net, r.n);
  EXPECT_GE(r.pitch, (9 * r.n + 9) / 10);
}

TEST(SimClosedLoop, WithTenPercentASecondMoveReachesTheBand) {
  // Near neutral after the first move, the lift (and the 10 % riding on it)
  // is small: the second move, planned from the first move's mission, lands.
  const SimHarness h;
  Rates r;
  for (const SimLoopCase& c : makeSimCases(kCases, kSeed)) {
    const SimOutcome o = h.runTwice(c, true);
    r.all += o.spec.all(), r.net += o.spec.net, r.safe += o.safe, ++r.n;
  }
  std::printf("  [sim, exact+0.5kg, coefficients known to 10 %%, two moves] spec %d, net %d, safe %d of %d\n", r.all,
              r.net, r.safe, r.n);
  EXPECT_EQ(r.safe, r.n);
  EXPECT_GE(r.all, (9 * r.n + 9) / 10);
}

TEST(SimClosedLoop, ACalibratedSigmaOverrideBehavesLikeKnownCoefficients) {
  // The planner alone: the analysis's estimates with 0.1 kg / 0.1 mm sigmas.
  const SimHarness h(SigmaOverride{0.1, 0.1, std::nullopt});
  const Rates r = run(h, "sigma override 0.1 kg, 0.1 mm");
  EXPECT_EQ(r.safe, r.n);
  EXPECT_GE(r.net, 9 * r.n / 10);
  EXPECT_GE(r.all, 9 * r.n / 10);
}

TEST(SimClosedLoop, ClassicTableInTheSameLoop) {
  // The classic table reads the analysis's depth, pitch and roll deviations.
  // With the simulator's integrating depth and pitch loops the depth and
  // pitch deviations are ~0, so it sees only roll.
  const SimHarness h;
  int reached = 0, one = 0;
  const auto cases = makeSimCases(10, kSeed);
  for (const SimLoopCase& c : cases) {
    const auto m = h.classicMissions(c, 8);
    reached += m.has_value();
    one += m && *m <= 1;
  }
  std::printf("  [sim, classic] spec within 8 missions in %d of %zu, after one in %d\n", reached, cases.size(), one);
  EXPECT_EQ(one, 0);
}

TEST(SimClosedLoop, TheCruiseEquivalentCgYLevelsTheVehicleAtCruise) {
  // The analysis's cruise.cg_y_mm is the CG y that gives the cruise roll at
  // rest (propeller torque included). Moving the true CG by minus that value
  // must level the vehicle at cruise rpm, and leave it rolled at rest by
  // the torque's share: the thesis's "a little heavier on port" (§5.3.3).
  const SimHarness h({}, 0.02);
  SimLoopCase c = makeSimCases(1, kSeed).front();
  c.light_kg = 0.6;
  c.x_mm = 0.0;
  c.y_mm = 1.0;
  c.water2 = c.water1;
  const SimMission first = h.fly(c, c.installed_kg, c.water1, c.seed);
  const double y_cruise = first.report.at("cruise").at("cg_y_mm").get<double>();
  ASSERT_GT(std::abs(first.cruise_roll_deg), 1.0);  // the torque rolls it several degrees
  SimLoopCase levelled = c;
  levelled.y_mm = c.y_mm - y_cruise;
  const SimMission second = h.fly(levelled, c.installed_kg, c.water1, c.seed + 1);
  // 0.03 deg: under a third of the roll band; the residual (~0.7 % of the
  // torque roll) is the flight condition shifting a little with the trim.
  EXPECT_NEAR(second.cruise_roll_deg, 0.0, 0.03);
  EXPECT_NEAR(second.roll_deg, -(first.cruise_roll_deg - first.roll_deg), 0.05);  // static roll = minus the torque's
}
