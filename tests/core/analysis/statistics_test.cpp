#include "analysis/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using auv::analysis::MeanAccumulator;
using auv::analysis::MeanEstimate;
using auv::analysis::studentT975;

TEST(StudentT, MatchesExactFormsAndPublishedTable) {
  // nu = 1 and 2 have closed forms; the others are A&S Table 26.10 values
  // outside the interpolation table (40, 60, 120) and the normal limit.
  EXPECT_NEAR(studentT975(1), std::tan(std::numbers::pi * 0.475), 1e-4);
  EXPECT_NEAR(studentT975(2), 0.95 / std::sqrt(2 * 0.975 * 0.025), 1e-4);
  EXPECT_NEAR(studentT975(40), 2.0211, 2e-4);
  EXPECT_NEAR(studentT975(60), 2.0003, 2e-4);
  EXPECT_NEAR(studentT975(120), 1.9799, 2e-4);
  EXPECT_NEAR(studentT975(1e9), 1.95996, 1e-4);
  // Fractional degrees of freedom lie between their neighbours.
  EXPECT_LT(studentT975(2.5), studentT975(2));
  EXPECT_GT(studentT975(2.5), studentT975(3));
}

TEST(MeanAccumulator, WhiteNoiseKeepsItsSampleSize) {
  std::mt19937 rng(1);
  std::normal_distribution<double> n(5.0, 2.0);
  MeanAccumulator acc;
  for (int i = 0; i < 20000; ++i) acc.add(n(rng));
  const MeanEstimate e = acc.result();
  EXPECT_NEAR(e.mean, 5.0, 0.05);
  EXPECT_NEAR(e.sd, 2.0, 0.05);
  EXPECT_LT(e.lag1, 0.03);
  EXPECT_GT(e.n_eff, 0.93 * 20000);
  EXPECT_NEAR(e.ci95, 1.96 * 2.0 / std::sqrt(20000.0), 0.003);
}

// AR(1) noise: the interval must cover the true mean about 95 % of the time.
// An interval that ignored autocorrelation (phi = 0.9) would cover ~41 %.
TEST(MeanAccumulator, Ar1IntervalHasNominalCoverage) {
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  const double phi = 0.9;
  int covered = 0, naive_covered = 0;
  const int trials = 400;
  for (int k = 0; k < trials; ++k) {
    MeanAccumulator acc;
    double x = n(rng) / std::sqrt(1 - phi * phi);
    for (int i = 0; i < 3000; ++i) {
      x = phi * x + n(rng);
      acc.add(10.0 + x);
    }
    const MeanEstimate e = acc.result();
    covered += std::abs(e.mean - 10.0) <= e.ci95;
    naive_covered += std::abs(e.mean - 10.0) <= 1.96 * e.sd / std::sqrt(3000.0);
    if (k == 0) {
      EXPECT_NEAR(e.n_eff / 3000.0, (1 - phi) / (1 + phi), 0.02);
    }
  }
  const double frac = static_cast<double>(covered) / trials;
  EXPECT_GT(frac, 0.91);
  EXPECT_LT(frac, 0.99);
  EXPECT_LT(static_cast<double>(naive_covered) / trials, 0.6);
}

TEST(MeanAccumulator, LargeOffsetDoesNotCancel) {
  MeanAccumulator acc;
  for (int i = 0; i < 100000; ++i) acc.add(3000.0 + ((i % 2) ? 1e-4 : -1e-4));
  const MeanEstimate e = acc.result();
  EXPECT_NEAR(e.mean, 3000.0, 1e-9);
  EXPECT_NEAR(e.sd, 1e-4, 1e-9);
  EXPECT_EQ(e.lag1, 0.0);  // alternating signs: negative correlation clamped to 0
}

TEST(MeanAccumulator, BlockScatterWidensTheInterval) {
  // Four legs with nearly noise-free but different means: the mission mean
  // is uncertain by the spread of the legs, not by the tiny within-leg noise.
  MeanAccumulator acc;
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 0.001);
  for (int b = 0; b < 4; ++b) {
    for (int i = 0; i < 1000; ++i) acc.add(b + n(rng));
    acc.endBlock();
  }
  const MeanEstimate e = acc.result();
  EXPECT_EQ(e.blocks, 4u);
  EXPECT_NEAR(e.mean, 1.5, 1e-3);
  // Block means 0..3: sd 1.291, se 0.6455, t(3) = 3.1824.
  EXPECT_NEAR(e.ci95, 3.1824 * std::sqrt(5.0 / 3.0) / 2.0, 1e-3);
}

TEST(MeanAccumulator, EmptyAndSingle) {
  MeanAccumulator acc;
  EXPECT_FALSE(acc.result().valid());
  acc.add(2.5);
  const MeanEstimate e = acc.result();
  EXPECT_EQ(e.mean, 2.5);
  EXPECT_TRUE(std::isinf(e.ci95));
}
