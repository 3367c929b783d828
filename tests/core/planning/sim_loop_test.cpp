// The closed loop with the simulator as truth and the real analysis (issue
// #6 item 5): mission -> analyze -> plan -> apply -> mission on HUGIN. The
// printed rates are those in docs/decisions/planning-closed-loop.md.
#include <gtest/gtest.h>

#include <cstdio>

#include "sim_loop.h"

using namespace auv;
using namespace auv::closed_loop;

namespace {

constexpr int kCases = 30;
constexpr std::uint64_t kSeed = 2026;

struct Rates {
  int all = 0, net = 0, pitch = 0, roll = 0, depth = 0, safe = 0, n = 0;
  int reachable = 0, all_reachable = 0;  // cases whose pitch band the kit can reach at all
};

Rates run(const SimHarness& h, const char* label) {
  Rates r;
  for (const SimLoopCase& c : makeSimCases(kCases, kSeed)) {
    const SimOutcome o = h.runOnce(c, PlanPolicy::Exact, true);
    r.all += o.spec.all(), r.net += o.spec.net, r.pitch += o.spec.pitch, r.roll += o.spec.roll;
    r.depth += o.spec.depth, r.safe += o.safe, ++r.n;
    r.reachable += o.reachable, r.all_reachable += o.reachable && o.spec.all();
  }
  std::printf("  [sim, exact+0.5kg, %s] spec %d, net %d, pitch %d, roll %d, depth %d, safe %d of %d; "
              "spec %d of the %d whose pitch band the kit can reach\n",
              label, r.all, r.net, r.pitch, r.roll, r.depth, r.safe, r.n, r.all_reachable, r.reachable);
  return r;
}

}  // namespace

TEST(SimClosedLoop, WithTheAnalysisOwnSigmaTheMoveIsSafeButAboveTheBand) {
  // The analysis states 0.5-1.7 kg for net buoyancy on these logs (10 %
  // hydrodynamic-coefficient uncertainty); its estimates are far better than
  // that, but the plan must trust the stated sigma: the 95 % margin lifts
  // the target above 1.2 kg.
  const SimHarness h;
  const Rates r = run(h, "analysis sigma");
  EXPECT_EQ(r.safe, r.n);
  EXPECT_EQ(r.depth, r.n);   // the depth loop integrates: the depth error is ~0
  EXPECT_LT(r.net, r.n / 2);  // documented: the stated sigma, not the planner, decides
}

TEST(SimClosedLoop, WithACalibratedSigmaNetBuoyancyLandsInBand) {
  // The same estimates with 0.1 kg / 0.1 mm sigmas (their actual error on
  // these logs): net buoyancy and depth meet the spec; pitch (+-0.17 mm of
  // CG x at BG 20 mm) and roll (the analysis's CG y is ~0.06 mm off here,
  // 0.17 deg) do not in every case.
  const SimHarness h(SigmaOverride{0.1, 0.1, std::nullopt});
  const Rates r = run(h, "calibrated sigma");
  EXPECT_EQ(r.safe, r.n);
  EXPECT_GE(r.net, 9 * r.n / 10);
  EXPECT_GE(r.depth, 9 * r.n / 10);
  EXPECT_GT(r.all, 0);
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
