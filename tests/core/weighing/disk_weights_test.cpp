#include "weighing/disk_weights.h"

#include <gtest/gtest.h>

#include <cmath>

#include "report_matlab.h"
#include "slocum_test_support.h"

namespace auv {
namespace {

using namespace slocum_test;

// App. B h after the battery move, computed the report's way (its posncalc
// h_out is physically right; see roll_correction_test).
double appendixBHRoll() {
  const double mass[3] = {0.5, 0.6, 0.7}, reading[3] = {0.10, 0.14, 0.16};
  double h = 0.0;
  for (int i = 0; i < 3; ++i) h += report::hArm(mass[i], reading[i], kReportBeta, kAppBMassKg) / 3.0;
  return report::posncalc(h, kReportBeta, kAppBMassKg, kAppBBatteryKg).h_out;
}

// Disk transfers of the report's arrangements 0..7 (del_m1 ... del_m7), kg.
constexpr double At = 0.550, Bt = 0.0, Ct = 0.555, Ab = 0.0, Bb = 0.555, Cb = 0.0;
const double kDel[8] = {0.0, At - Ab, Bt - Bb, Ct - Cb, At - Ab + Bt - Bb, At - Ab + Ct - Cb, Bt - Bb + Ct - Cb,
                        At - Ab + Bt - Bb + Ct - Cb};

}  // namespace

TEST(DiskWeights, AppendixBPrintedArrangementsFromTheReportCode) {
  // (b) App. B prints h for "max ballast change" and arrangements 1..7:
  const double printed[8] = {0.0056666, 0.0063335, 0.004181, 0.0063469, 0.0056532, 0.0078191, 0.0056666, 0.0063335};
  const double h_roll = appendixBHRoll();
  EXPECT_NEAR(h_roll, 0.0054181, 5e-8);
  for (int k = 0; k < 8; ++k) {
    const double hk = report::newhcalc(At + Bt + Ct, Ab + Bb + Cb, kDel[k], kAppBMassKg, h_roll);
    EXPECT_NEAR(report::last(kAppBMassKg, 288, 288, hk).h_out, printed[k], 5e-8) << k;
  }
  // "Which Arrangement ... 1 -> upper 450 g, lower 126 g".
  const report::Last a1 = report::last(kAppBMassKg, 288, 288, report::newhcalc(1.105, 0.555, kDel[1], kAppBMassKg, h_roll));
  EXPECT_DOUBLE_EQ(a1.upper_out, 450.0);
  EXPECT_DOUBLE_EQ(a1.lower_out, 126.0);
}

TEST(DiskWeights, AppendixBCorrectedArrangements) {
  const double M = kAppBMassKg, h_roll = appendixBHRoll();
  const HArmCorrection hc = correctHArm(layout(), appendixBAfterTankStep(), M, h_roll);
  const double span = 0.072 + 0.058;  // upper 72 mm above, lower 58 mm below the axis
  for (int k = 0; k < 8; ++k) {
    const DiskArrangement& a = hc.arrangements[static_cast<std::size_t>(k)];
    // Swapping disks is right in the report (newhcalc = h + 2 r dm / M).
    EXPECT_NEAR(a.h_after_swap_m, report::newhcalc(1.105, 0.555, kDel[k], M, h_roll), 1e-15) << k;
    EXPECT_NEAR(a.h_after_swap_m, h_roll + 2.0 * 0.07 * kDel[k] / M, 1e-15) << k;
    // None reaches 6 mm: each moves the most the bottles allow (162 g),
    // downward if h is short, upward if long; h changes by 162 g * 0.13 m / M.
    const double dir = a.h_after_swap_m < 0.006 ? -1.0 : 1.0;
    EXPECT_NEAR(a.aft_shift_kg, dir * 0.162, 1e-12) << k;
    EXPECT_NEAR(a.h_m, a.h_after_swap_m - dir * 0.162 * span / M, 1e-15) << k;
    EXPECT_FALSE(a.reaches_target);
    EXPECT_NEAR(a.after.at(kAftUpper) + a.after.at(kAftLower), 0.576, 1e-12);
  }
  // Best: no swap, 162 g down: 5.4181 + 0.4027 = 5.8208 mm (report: 5.6667,
  // off by its y_g sign error, -2 (m_u r_u + m_l r_l) / M = -0.1542 mm).
  EXPECT_EQ(hc.chosen, 0);
  EXPECT_NEAR(hc.best().h_m, 0.0058208, 5e-8);
  EXPECT_NEAR(0.0056666 - hc.best().h_m, -2.0 * (0.288 * 0.072 - 0.288 * 0.058) / M, 5e-8);
  // The session's pick, arrangement 1 (printed 6.3335 mm), really gives
  // 5.4181 + 2 * 0.07 * 0.55 / M - 0.4027 = 6.4877 mm.
  EXPECT_NEAR(hc.arrangements[1].h_m, 0.0064877, 5e-8);
  EXPECT_NEAR(hc.best().after.at(kAftUpper), 0.126, 1e-12);
  EXPECT_NEAR(hc.best().after.at(kAftLower), 0.450, 1e-12);
}

TEST(DiskWeights, ReachableTargetNeedsOnlyTheBottles) {
  // h = 5.9 mm, M = 52 kg: 52 * 0.1 mm / 0.13 m = 40 g from upper to lower.
  SlocumBallast b;
  b.at(kAftUpper) = b.at(kAftLower) = 0.200;
  b.disks[0] = {0.5, 0.0};
  const HArmCorrection hc = correctHArm(layout(), b, 52.0, 0.0059);
  EXPECT_EQ(hc.chosen, 0);
  EXPECT_TRUE(hc.best().reaches_target);
  EXPECT_NEAR(hc.best().aft_shift_kg, -0.040, 1e-12);
  EXPECT_NEAR(hc.best().h_m, 0.006, 1e-12);
}

TEST(DiskWeights, DiskSwapWhenTheBottlesCannotReach) {
  // h = 4 mm with empty aft bottles: only a disk swap helps. Swapping A
  // (0.3 kg top) lowers G by 2 * 0.07 * 0.3 / 50 = 0.84 mm; swapping C
  // (0.7 kg top) by 1.96 mm, which lands on 5.96 mm: the closest.
  SlocumBallast b;
  b.disks[0] = {0.3, 0.0};
  b.disks[2] = {0.7, 0.0};
  const HArmCorrection hc = correctHArm(layout(), b, 50.0, 0.004);
  EXPECT_EQ(hc.chosen, 3);
  EXPECT_NEAR(hc.best().h_m, 0.004 + 2.0 * 0.07 * 0.7 / 50.0, 1e-15);
  EXPECT_NEAR(hc.best().after.disks[2].bottom_kg, 0.7, 1e-15);
  EXPECT_NEAR(hc.best().after.disks[2].top_kg, 0.0, 1e-15);
  EXPECT_FALSE(hc.best().reaches_target);
}

TEST(DiskWeights, NeedlessSwapsAreNotRecommended) {
  // Column B holds equal disks top and bottom: swapping it changes nothing,
  // so the arrangement without it wins the tie.
  SlocumBallast b;
  b.at(kAftUpper) = b.at(kAftLower) = 0.200;
  b.disks[1] = {0.3, 0.3};
  const HArmCorrection hc = correctHArm(layout(), b, 52.0, 0.0059);
  EXPECT_NEAR(hc.arrangements[2].h_m, hc.arrangements[0].h_m, 1e-15);
  EXPECT_EQ(hc.chosen, 0);
}

}  // namespace auv
