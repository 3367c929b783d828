#include "hydrostatics/static_trim.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/units.h"
#include "hydrostatics/restoring.h"

namespace auv {

using Eigen::Vector3d;

TEST(StaticTrim, CgForwardPitchesNoseDown) {
  // x offset 10 mm, BG 20 mm: theta = -atan(10/20) = -26.565 deg (exact).
  const auto t = staticTrimFromOffset({0.010, 0, 0.020});
  EXPECT_NEAR(units::radToDeg(t.pitch_rad), -26.56505117707799, 1e-9);
  EXPECT_NEAR(t.roll_rad, 0.0, 1e-15);
  EXPECT_TRUE(t.stable);
}

TEST(StaticTrim, CgToStarboardRollsStarboardDown) {
  const auto t = staticTrimFromOffset({0, 0.001, 0.020});
  EXPECT_NEAR(units::radToDeg(t.roll_rad), units::radToDeg(std::atan(0.05)), 1e-12);
  EXPECT_GT(t.roll_rad, 0.0);
}

TEST(StaticTrim, EquilibriumZeroesTheRestoringMoments) {
  // Conservation check: at the returned attitude the moment rows of g(eta)
  // vanish, for combined offsets and for W != B.
  const double W = 15000, B = 14990;
  const Vector3d rg(0.012, -0.004, 0.018), rb(-0.003, 0.001, -0.011);
  const auto t = staticTrim(W, B, rg, rb);
  const auto g = restoringForces(W, B, rg, rb, t.roll_rad, t.pitch_rad);
  EXPECT_NEAR(g(3), 0.0, 1e-9);
  EXPECT_NEAR(g(4), 0.0, 1e-9);
  EXPECT_NEAR(g(5), 0.0, 1e-9);
  // and it is a minimum of potential energy: a small nudge is restored
  const auto gp = restoringForces(W, B, rg, rb, t.roll_rad, t.pitch_rad + 1e-3);
  EXPECT_GT(gp(4), 0.0);
}

TEST(StaticTrim, CgAboveCbIsReportedUnstable) {
  EXPECT_FALSE(staticTrimFromOffset({0, 0, -0.01}).stable);
}

}  // namespace auv
