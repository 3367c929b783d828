// Closed loop (issue #6 item 5): truth -> mission -> analysis -> plan ->
// apply -> mission, with the analytic truth of closed_loop.h. The numbers
// printed here are the ones in docs/decisions/planning-closed-loop.md; the
// full table comes from scripts/compare-policies.sh.
#include <gtest/gtest.h>

#include <cstdio>

#include "closed_loop.h"
#include "plan_fixture.h"

using namespace auv;
using namespace auv::closed_loop;

namespace {

constexpr int kCases = 60;
constexpr std::uint64_t kSeed = 2026;

struct Tally {
  int all = 0, net = 0, pitch = 0, roll = 0, safe = 0, n = 0, reachable = 0;
  double pc(int k) const { return 100.0 * k / n; }
};

Tally tally(const Harness& h, PlanPolicy policy, bool optional_pieces) {
  Tally t;
  for (const LoopCase& c : makeCases(h.vehicle(), kCases, kSeed)) {
    const Outcome o = h.runOnce(c, policy, optional_pieces);
    t.all += o.spec.all(), t.net += o.spec.net, t.pitch += o.spec.pitch, t.roll += o.spec.roll, t.safe += o.safe;
    t.reachable += o.reachable;
    ++t.n;
  }
  std::printf("  [%s%s] spec %.0f %%, net %.0f %%, pitch %.0f %%, roll %.0f %%, safe %.0f %% of %d (pitch band "
              "reachable with perfect knowledge in %d)\n",
              toString(policy), optional_pieces ? "+0.5kg" : "", t.pc(t.all), t.pc(t.net), t.pc(t.pitch),
              t.pc(t.roll), t.pc(t.safe), t.n, t.reachable);
  return t;
}

AnalysisNoise absolute(double net_kg, double x_mm, double y_mm) {
  AnalysisNoise n;
  n.net_a_kg = net_kg, n.net_b = 0;
  n.x_a_mm = x_mm, n.x_b = 0;
  n.y_a_mm = y_mm, n.y_b = 0;
  return n;
}

}  // namespace

TEST(ClosedLoop, CasesCoverTheIssueRanges) {
  const auto cases = makeCases(planning_test::hugin(), kCases, kSeed);
  ASSERT_EQ(cases.size(), static_cast<std::size_t>(kCases));
  int fwd = 0, stbd = 0;
  for (const auto& c : cases) {
    EXPECT_GE(c.light_kg, 1.0);
    EXPECT_LE(c.light_kg, 8.0);
    EXPECT_GE(std::abs(c.x_mm), 5.0);
    EXPECT_LE(std::abs(c.x_mm), 25.0);
    EXPECT_GE(std::abs(c.y_mm), 0.5);
    EXPECT_LE(std::abs(c.y_mm), 3.0);
    fwd += c.x_mm > 0, stbd += c.y_mm > 0;
  }
  EXPECT_GT(fwd, kCases / 4);
  EXPECT_LT(fwd, 3 * kCases / 4);
  EXPECT_GT(stbd, kCases / 4);
  EXPECT_LT(stbd, 3 * kCases / 4);
}

TEST(ClosedLoop, OneExactMoveMeetsTheSpecWhenTheEstimateIsGoodEnough) {
  // sigma 0.05 kg, 0.05 mm, 0.001 mm: half the analysis's realised error on
  // synthetic HUGIN logs. Target of issue #6: >= 90 % after ONE move.
  const Harness h(planning_test::hugin(), absolute(0.05, 0.05, 0.001));
  const Tally t = tally(h, PlanPolicy::Exact, true);
  EXPECT_GE(t.pc(t.all), 90.0);
  EXPECT_EQ(t.safe, t.n);
}

TEST(ClosedLoop, AtTheAnalysisRealisedAccuracy) {
  // sigma 0.1 kg, 0.1 mm, 0.002 mm: the pitch band (+-0.5 deg = +-0.17 mm at
  // BG 20 mm) is 1.7 sigma wide, so about 90 % is the ceiling for pitch.
  const Harness h(planning_test::hugin(), absolute(0.1, 0.1, 0.002));
  const Tally t = tally(h, PlanPolicy::Exact, true);
  EXPECT_GE(t.pc(t.all), 80.0);
  EXPECT_GE(t.pc(t.net), 95.0);
  EXPECT_GE(t.pc(t.roll), 95.0);
  EXPECT_EQ(t.safe, t.n);
  // Without the 0.5 kg piece the 1.2 kg steps decide: most moves miss a band.
  const Tally s = tally(h, PlanPolicy::Exact, false);
  EXPECT_LT(s.all, t.all);
}

TEST(ClosedLoop, AtTheAnalysisStatedSigmaSafetyHoldsButOneMoveIsNotEnough) {
  // The sigma the analysis states for HUGIN (10 % hydrodynamic-coefficient
  // uncertainty: 0.3-0.9 kg, 0.5-2 mm), errors drawn at that sigma. The 95 %
  // margin is then 0.5-1.5 kg of the 1.2 kg band: the move is safe, not in band.
  const Harness h(planning_test::hugin(), AnalysisNoise{});
  const Tally t = tally(h, PlanPolicy::Exact, true);
  EXPECT_GE(t.pc(t.safe), 88.0);  // one-sided 95 % promise, 60 cases
  EXPECT_LT(t.pc(t.all), 90.0);   // documented: the target needs a better estimate
}

TEST(ClosedLoop, ClassicTableNeedsManyMissions) {
  const Harness h(planning_test::hugin(), absolute(0.1, 0.1, 0.002));
  int one = 0, converged = 0, total = 0;
  for (const LoopCase& c : makeCases(h.vehicle(), kCases, kSeed)) {
    const auto m = h.classicMissions(c, 40);
    one += m && *m <= 1;
    if (m) ++converged, total += *m;
  }
  std::printf("  [classic] spec after one mission in %d of %d; within 40 missions in %d (mean %.1f)\n", one, kCases,
              converged, converged ? double(total) / converged : 0.0);
  // It moves 1.2 kg per point and mission: one mission never fixes 1-8 kg and 5-25 mm.
  EXPECT_EQ(one, 0);
  EXPECT_LT(converged, kCases / 2);
}
