// The numerical pieces against analytic cases: Savitzky-Golay derivatives of
// polynomials, Levenberg-Marquardt on a known curve, sparse selection on a
// linear problem with one true term, and the localisation's words.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "discrepancy/levenberg_marquardt.h"
#include "discrepancy/localisation.h"
#include "discrepancy/savitzky_golay.h"
#include "discrepancy/sparse_selection.h"

namespace auv::discrepancy {
namespace {

TEST(SavitzkyGolay, QuarticFitsReproducePolynomialDerivatives) {
  const double dt = 0.2;
  std::vector<double> y(101);
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double t = static_cast<double>(i) * dt;
    y[i] = 1.0 + 0.5 * t - 0.3 * t * t + 0.02 * t * t * t - 0.001 * t * t * t * t;
  }
  const Smoothed s = savitzkyGolay(y, dt, 6, 4);
  for (std::size_t i = 6; i + 6 < y.size(); ++i) {
    const double t = static_cast<double>(i) * dt;
    EXPECT_NEAR(s.value[i], y[i], 1e-9);
    EXPECT_NEAR(s.d1[i], 0.5 - 0.6 * t + 0.06 * t * t - 0.004 * t * t * t, 1e-8);
    EXPECT_NEAR(s.d2[i], -0.6 + 0.12 * t - 0.012 * t * t, 1e-7);
  }
  // Next to a gap the window shrinks; too close to it there is no value.
  y[50] = std::nan("");
  const Smoothed g = savitzkyGolay(y, dt, 6, 4);
  EXPECT_TRUE(std::isnan(g.value[50]));
  EXPECT_TRUE(std::isnan(g.d1[49]));  // one sample to the gap: below the minimum half window
  EXPECT_NEAR(g.d1[46], 0.5 - 0.6 * 9.2 + 0.06 * 9.2 * 9.2 - 0.004 * 9.2 * 9.2 * 9.2, 1e-8);
}

TEST(LevenbergMarquardt, FitsAnExponentialWithinBounds) {
  std::vector<double> t(40), y(40);
  for (std::size_t i = 0; i < t.size(); ++i) {
    t[i] = 0.25 * static_cast<double>(i);
    y[i] = 3.0 * std::exp(-0.7 * t[i]) + 0.5;
  }
  LmProblem p;
  p.residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    r.resize(static_cast<Eigen::Index>(t.size()));
    for (std::size_t i = 0; i < t.size(); ++i) r[static_cast<Eigen::Index>(i)] = x[0] * std::exp(-x[1] * t[i]) + x[2] - y[i];
  };
  p.scale = Eigen::Vector3d(1.0, 0.1, 0.1);
  p.lower = Eigen::Vector3d(0.0, 0.0, -10.0);
  p.upper = Eigen::Vector3d(10.0, 5.0, 10.0);
  const LmResult r = levenbergMarquardt(p, Eigen::Vector3d(1.0, 0.2, 0.0));
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.x[0], 3.0, 1e-6);
  EXPECT_NEAR(r.x[1], 0.7, 1e-6);
  EXPECT_NEAR(r.x[2], 0.5, 1e-6);
  // A bound that excludes the answer holds.
  p.upper[1] = 0.5;
  EXPECT_LE(levenbergMarquardt(p, Eigen::Vector3d(1.0, 0.2, 0.0)).x[1], 0.5);
}

// e = nuisance + 2 x column 2 + noise over 12 units; columns 3, 4 unrelated,
// column 5 a copy of column 2 (not identifiable from it).
struct Linear {
  Eigen::MatrixXd J;
  Eigen::VectorXd e;
  std::vector<int> unit;
};
Linear makeLinear(double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  const int N = 1200;
  Linear L{Eigen::MatrixXd(N, 6), Eigen::VectorXd(N), std::vector<int>(N)};
  for (int i = 0; i < N; ++i) {
    const double x = i / 100.0;
    L.J(i, 0) = 1.0;
    L.J(i, 1) = std::sin(x);
    L.J(i, 2) = x * x / 50.0;
    L.J(i, 3) = std::cos(3.0 * x);
    L.J(i, 4) = n(rng);
    L.J(i, 5) = L.J(i, 2);
    L.e[i] = 0.3 + 0.1 * L.J(i, 1) + 2.0 * L.J(i, 2) + noise * n(rng);
    L.unit[static_cast<std::size_t>(i)] = i / 100;
  }
  return L;
}

// A parameter whose bounds meet is held (the model check's calibration
// constants held at the analysis's values, and its refits with one of them
// shifted). The others must reach their optimum given it, even when they are
// nearly collinear with it: the linear least-squares solution is the oracle.
TEST(LevenbergMarquardt, AHeldParameterLeavesTheOthersAtTheirConditionalOptimum) {
  const int n = 200;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  Eigen::VectorXd x(n), z(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = -1.0 + 2.0 * i / (n - 1.0);
    z[i] = x[i] + 0.05 * std::sin(7.0 * x[i]);  // 99.9 % collinear with x
    y[i] = 1.5 * x[i] + 2.0 * z[i] + 0.3 + noise(rng);
  }
  const double heldB = 2.4;  // 0.4 off the value the data would give
  LmProblem p;
  p.residuals = [&](const Eigen::VectorXd& q, Eigen::VectorXd& r) { r = q[0] * x + q[1] * z + Eigen::VectorXd::Constant(n, q[2]) - y; };
  p.scale = Eigen::Vector3d(1.0, 1.0, 0.1);
  p.lower = Eigen::Vector3d(-10.0, heldB, -10.0);
  p.upper = Eigen::Vector3d(10.0, heldB, 10.0);
  Eigen::MatrixXd A(n, 2);
  A.col(0) = x;
  A.col(1).setOnes();
  const Eigen::Vector2d oracle = A.colPivHouseholderQr().solve(y - heldB * z);
  // Started where a fit with the constant at its unshifted value ended.
  const LmResult r = levenbergMarquardt(p, Eigen::Vector3d(1.5, heldB, 0.3));
  EXPECT_DOUBLE_EQ(r.x[1], heldB);
  EXPECT_NEAR(r.x[0], oracle[0], 1e-6);
  EXPECT_NEAR(r.x[2], oracle[1], 1e-6);
  EXPECT_GT(std::abs(oracle[0] - 1.5), 0.3);  // the held shift does move the others
}

TEST(SparseSelection, StepwiseAndStlsqFindTheOneTrueColumn) {
  const Linear L = makeLinear(0.5, 3);
  const LinearProblem lp = buildLinearProblem(L.J, L.e, L.unit, 12, 2, 1200.0);
  const SelectionResult s = forwardStepwise(lp, {2, 3, 4}, std::vector<double>(12, 1.0), {}, true);
  ASSERT_EQ(s.selected.size(), 1u);
  EXPECT_EQ(s.selected[0], 2);
  const SubsetFit f = fitSubset(lp, {0, 1, 2}, std::vector<double>(12, 1.0));
  EXPECT_NEAR(f.beta[2], 2.0, 4.0 * f.sigma[2]);
  EXPECT_EQ(stlsq(lp, {2, 3, 4}, 0.5), std::vector<int>({2}));
  const std::vector<double> p = inclusionProbabilities(lp, {2, 3, 4}, 40, 9, {});
  EXPECT_GT(p[0], 0.9);
  EXPECT_LT(p[1], 0.2);
  EXPECT_LT(p[2], 0.2);
  EXPECT_LT(crossValidationError(lp, {0, 1, 2}, 4), crossValidationError(lp, {0, 1}, 4));
}

// Two columns that each explain the same effect (column 5 = column 2 plus a
// little of its own shape): the bootstrap picks one or the other, hardly
// ever both, so each alone falls short of a firm inclusion while the pair
// is nearly always there (rivals, term_acceptance.h).
TEST(SparseSelection, RivalColumnsSplitTheBootstrapAndAreRarelyTogether) {
  Linear L = makeLinear(0.5, 3);
  for (Eigen::Index i = 0; i < L.e.size(); ++i) L.J(i, 5) = L.J(i, 2) + 0.01 * std::sin(0.07 * static_cast<double>(i));
  const LinearProblem lp = buildLinearProblem(L.J, L.e, L.unit, 12, 2, 1200.0);
  const Inclusion in = inclusionStatistics(lp, {2, 3, 5}, 60, 9, {});
  EXPECT_GT(in.p[0] + in.p[2] - in.together(0, 2), 0.9);
  EXPECT_LT(in.together(0, 2), 0.1);
  EXPECT_GT(std::min(in.p[0], in.p[2]), 0.1);
  EXPECT_DOUBLE_EQ(in.together(1, 1), in.p[1]);
  EXPECT_DOUBLE_EQ(in.together(0, 2), in.together(2, 0));
}

TEST(SparseSelection, PureNoiseSelectsNothing) {
  Linear L = makeLinear(0.5, 5);
  for (Eigen::Index i = 0; i < L.e.size(); ++i) L.e[i] -= 2.0 * L.J(i, 2);
  const LinearProblem lp = buildLinearProblem(L.J, L.e, L.unit, 12, 2, 1200.0);
  EXPECT_TRUE(forwardStepwise(lp, {2, 3, 4}, std::vector<double>(12, 1.0), {}, true).selected.empty());
}

TEST(SparseSelection, CollinearCandidatesAreReported) {
  const Linear L = makeLinear(0.5, 3);
  const LinearProblem lp = buildLinearProblem(L.J, L.e, L.unit, 12, 2, 1200.0);
  const Collinearity c = collinearity(lp, {2, 3, 5});
  EXPECT_NEAR(c.correlation(0, 2), 1.0, 1e-9);
  EXPECT_LT(std::abs(c.correlation(0, 1)), 0.5);
}

SampleTable table(std::size_t n) {
  SampleTable s;
  for (std::size_t i = 0; i < n; ++i) {
    s.t.push_back(static_cast<double>(i) * 10.0);
    s.block.push_back(static_cast<int>(i / 50));
    s.unit.push_back(static_cast<int>(i / 100));
    s.phase.push_back(i % 100 < 50 ? Phase::kDive : Phase::kClimb);
    s.pressure_dbar.push_back(static_cast<double>(i % 50) * 6.0);  // 0..294 dbar
    s.temperature_degC.push_back(10.0);
    s.speed_mps.push_back(0.3 + 0.01 * static_cast<double>(i % 7));
    s.rpm.push_back(std::nan(""));
    s.pitch_deg.push_back(i % 100 < 50 ? -25.0 : 25.0);
    s.since_actuator_s.push_back(static_cast<double>(i % 50) * 10.0);
  }
  return s;
}

TEST(Localisation, DescribesAPressureTrendBelowAHinge) {
  const SampleTable s = table(1000);
  std::vector<double> r(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) r[i] = -0.009 * std::max(0.0, s.pressure_dbar[i] - 150.0) / 100.0;
  const Localisation L = localise(s, r, Channel::kVerticalVelocity, "test");
  ASSERT_FALSE(L.ranked.empty());
  EXPECT_EQ(L.ranked.front().factor, "pressure");
  EXPECT_NE(L.summary.find("grows 0.900 cm/s per 100 dbar below"), std::string::npos) << L.summary;
  EXPECT_NE(L.summary.find("independent of speed"), std::string::npos) << L.summary;
}

TEST(Localisation, NamesAPhaseAndAConstant) {
  const SampleTable s = table(1000);
  std::vector<double> r(s.size()), c(s.size(), 0.3);
  for (std::size_t i = 0; i < s.size(); ++i) r[i] = s.phase[i] == Phase::kClimb ? 0.012 : -0.002;
  const std::string phase = localise(s, r, Channel::kVerticalVelocity, "test").summary;
  EXPECT_NE(phase.find("largest during climbs: mean 1.20 cm/s (dives -0.200)"), std::string::npos) << phase;
  EXPECT_NE(localise(s, c, Channel::kDepth, "test").summary.find("constant 0.300 m everywhere"), std::string::npos);
}

}  // namespace
}  // namespace auv::discrepancy
