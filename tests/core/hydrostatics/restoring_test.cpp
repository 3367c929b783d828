#include "hydrostatics/restoring.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace auv {

using Eigen::Vector3d;

TEST(Restoring, UprightNeutralBodyWithCgBelowCbHasNoForce) {
  const auto g = restoringForces(1000, 1000, {0, 0, 0.02}, {0, 0, 0}, 0, 0);
  EXPECT_NEAR(g.norm(), 0.0, 1e-12);
}

TEST(Restoring, HeavyBodySinks) {
  // tau = ... + g: heave row is -(W - B) cos cos; a heavy body needs
  // tau_z = -(W - B) (upward) to hold station, so g_z = -(W - B).
  const auto g = restoringForces(1010, 1000, {0, 0, 0}, {0, 0, 0}, 0, 0);
  EXPECT_DOUBLE_EQ(g(2), -10.0);
}

TEST(Restoring, PitchMomentOpposesPitchWhenBottomHeavy) {
  // Nose-up pitch of a bottom-heavy body: restoring g_M = W*BG*sin(theta) > 0
  // on the left side, i.e. a nose-down moment -g_M on the right side.
  const double W = 1000, bg = 0.02, th = 0.1;
  const auto g = restoringForces(W, W, {0, 0, bg}, {0, 0, 0}, 0, th);
  EXPECT_NEAR(g(4), W * bg * std::sin(th), 1e-12);
  const auto gr = restoringForces(W, W, {0, 0, bg}, {0, 0, 0}, 0.1, 0);
  EXPECT_NEAR(gr(3), W * bg * std::sin(0.1), 1e-12);
}

TEST(Restoring, MomentsMatchCrossProductOfWeightAndBuoyancy) {
  // Independent oracle: moments = r_g x f_g + r_b x f_b with the forces
  // rotated into body axes; g(eta) is minus that sum.
  const double W = 1200, B = 1180, phi = 0.3, th = -0.2;
  const Vector3d rg(0.05, -0.01, 0.03), rb(-0.02, 0.004, -0.01);
  const Vector3d n(-std::sin(th), std::cos(th) * std::sin(phi), std::cos(th) * std::cos(phi));
  const Vector3d fg = W * n, fb = -B * n;
  const Vector3d m = rg.cross(fg) + rb.cross(fb);
  const auto g = restoringForces(W, B, rg, rb, phi, th);
  EXPECT_NEAR(g(0), -(fg + fb).x(), 1e-9);
  EXPECT_NEAR(g(1), -(fg + fb).y(), 1e-9);
  EXPECT_NEAR(g(2), -(fg + fb).z(), 1e-9);
  EXPECT_NEAR(g(3), -m.x(), 1e-9);
  EXPECT_NEAR(g(4), -m.y(), 1e-9);
  EXPECT_NEAR(g(5), -m.z(), 1e-9);
}

TEST(Restoring, NaturalPeriodOfPendulum) {
  // A point mass m on a massless rod of length L: I = m L^2, W = m g, BG = L
  // -> T = 2 pi sqrt(L / g).
  const double m = 2.0, L = 0.5, g0 = 9.80665;
  EXPECT_NEAR(restoringPeriod(m * L * L, m * g0, L), 2 * std::numbers::pi * std::sqrt(L / g0), 1e-12);
}

}  // namespace auv
