// The small CTest version of bench/model_check_truths_bench (issue 11 item
// 6): concealed-effect AUV logs whose truth is drawn away from the profile
// (hydrodynamic groups x 0.6..1.4, Munk inside M_w or on top, torque 0..2x,
// planes 0.6..1.2; auv_truth_draw.h), the check given only the nominal
// profile. Controls (one with no propeller torque at all) must name nothing,
// the propeller torque is never missing physics (it is calibrated), and the
// concealed effect is the top term within 30 %. The full rates, all five
// effects over several truths each, are the benchmark's.
#include <gtest/gtest.h>

#include "drawn_truths_harness.h"

namespace auv::discrepancy::test {
namespace {

const Delphin2Nominal& nominal() {
  static const Delphin2Nominal d;
  return d;
}

// The first truth of each case in the benchmark (seeds 100 * (case + 1)).
TEST(DrawnTruths, ControlsNameNothingAndTheTorqueIsCalibrated) {
  const std::vector<DrawnCase> cases = drawnCases();
  for (std::size_t k = 0; k < 2; ++k) {
    const DrawnOutcome o = runDrawnCase(nominal(), cases[k], {100 * (k + 1)}, true);
    printDrawnRow(o);
    EXPECT_EQ(o.false_terms, 0) << cases[k].label;
    EXPECT_EQ(o.torque_missing, 0) << cases[k].label;
  }
}

TEST(DrawnTruths, ConcealedEffectsAreMostlyTheTopTerm) {
  // Thermal expansion, mass drift, pitch sensor bias: the benchmark's rates
  // over all five effects are the proof; here at least two of three.
  const std::vector<DrawnCase> cases = drawnCases();
  int top1 = 0;
  for (std::size_t k = 3; k < 6; ++k) {
    const DrawnOutcome o = runDrawnCase(nominal(), cases[k], {100 * (k + 1)}, true);
    printDrawnRow(o);
    top1 += o.within30;
    EXPECT_EQ(o.torque_missing, 0) << cases[k].label;
  }
  EXPECT_GE(top1, 2);
}

TEST(DrawnTruths, ADampingIsJudgedOnShortReplays) {
  // Truth 700 (M_q' x 0.79, M_|q|q x 2): replayed over the whole log the
  // true vehicle itself scored worse than the fitted base without the term
  // (depth 0.072 against 0.058 m^2), so the term was refused. Replayed in
  // 90 s horizons restarted from the log, the damping shows. Its formal
  // sigma left the truth 4.5 sigma away (1.18 +- 0.04 for 1.0); the values
  // fitted on the two held-out halves differ by 0.38, and the stated sigma
  // now includes that spread.
  const DrawnCase c = drawnCases()[6];
  ASSERT_EQ(c.expected, "quadratic_pitch_damping");
  const DrawnOutcome o = runDrawnCase(nominal(), c, {700}, true);
  printDrawnRow(o);
  EXPECT_EQ(o.top1, 1);
  EXPECT_EQ(o.within30, 1);
  EXPECT_EQ(o.covered2, 1);
  EXPECT_EQ(o.false_terms, 0);
}

TEST(DrawnTruths, AVehicleThatSurfacesMidLogStillShowsItsMassDrift) {
  // Truth 503 is buoyant enough to surface on its slow legs. Replayed through
  // the surface and back down, the replay lagged the next glide by 1.2 m and
  // the true mass drift made the held-out replay worse (cost 5 -> 5.34); a
  // vertical current was named instead. The replay now restarts after a
  // surface interval, in motion from the logged state.
  const DrawnCase c = drawnCases()[4];
  ASSERT_EQ(c.expected, "mass_drift");
  const DrawnOutcome o = runDrawnCase(nominal(), c, {503}, true);
  printDrawnRow(o);
  EXPECT_EQ(o.top1, 1);
  EXPECT_EQ(o.within30, 1);
  EXPECT_EQ(o.false_terms, 0);
}

TEST(DrawnTruths, AMunkInsideControlNamesNoVerticalCurrent) {
  // Truth 105 (Munk moment inside M_w, heave x 0.81) is a control. The check
  // named a steady downward current of 0.9 mm/s on it, and it found one of
  // 0.3-0.9 mm/s on every Munk-inside control, noise-free logs too: a stand-in
  // for the calibrated groups, not water motion. The AUV check no longer
  // offers a survey-long vertical current.
  const DrawnCase c = drawnCases()[0];
  ASSERT_TRUE(c.expected.empty());
  const DrawnOutcome o = runDrawnCase(nominal(), c, {105}, true);
  printDrawnRow(o);
  EXPECT_EQ(o.false_terms, 0);
  EXPECT_EQ(o.torque_missing, 0);
}

}  // namespace
}  // namespace auv::discrepancy::test
