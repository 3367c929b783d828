// The identification harness on a few drawn truths (the full proof over 50
// is bench/identification_bench): the truth's hydrodynamics are not the
// profile's (groups x0.6-1.4, Munk inside M_w or on top, torque 0-2x,
// planes x0.6-1.2), the analysis gets only the nominal profile and the log.
// Bounds are what the calibration meets on these seeds with some headroom;
// before the calibration (flat 10 % coefficient term, profile assumed
// exact) the bench's 50 truths had 2-sigma coverage of CG x in 22 of 49.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "identification_harness.h"

namespace auv::identification {
namespace {

TEST(Identification, DrawnTruthsAreCoveredByThePosteriorSigma) {
  const Harness h;
  int known = 0, cov_net = 0, cov_x = 0, cov_y = 0, y_known = 0;
  std::vector<double> net_err, x_err;
  for (std::uint64_t seed = 1100; seed < 1108; ++seed) {
    const CaseResult r = h.run(seed, false);
    SCOPED_TRACE(r.truth.describe());
    if (r.known) {
      ++known;
      net_err.push_back(std::abs(r.net_err_kg));
      x_err.push_back(std::abs(r.x_err_mm));
      cov_net += std::abs(r.net_err_kg) <= 2 * r.net_sigma_kg;
      cov_x += std::abs(r.x_err_mm) <= 2 * r.x_sigma_mm;
    }
    if (r.y_known) {
      ++y_known;
      cov_y += std::abs(r.y_err_mm) <= 2 * r.y_sigma_mm;
    }
  }
  ASSERT_EQ(known, 8);
  ASSERT_EQ(y_known, 8);
  std::sort(net_err.begin(), net_err.end());
  std::sort(x_err.begin(), x_err.end());
  std::printf("  8 truths: net |err| median %.3f kg, CG x |err| median %.2f mm; coverage %d %d %d of 8\n",
              0.5 * (net_err[3] + net_err[4]), 0.5 * (x_err[3] + x_err[4]), cov_net, cov_x, cov_y);
  EXPECT_GE(cov_net, 7);
  EXPECT_GE(cov_x, 7);
  EXPECT_GE(cov_y, 7);
  EXPECT_LT(0.5 * (net_err[3] + net_err[4]), 0.3);
  EXPECT_LT(0.5 * (x_err[3] + x_err[4]), 1.0);
}

// Vehicles the steady windows lose: 1109 limit-cycles at its two lower
// speeds (pitch +-6 deg, period ~10 min), 1136 cannot hold depth at two of
// its three (the elevator at its stop, sinking at -20 deg or climbing at
// +15 deg). Before the averaged legs and the steady dives, the analysis
// kept one speed of each and stated 2.9 and 7.6 kg of sigma (now 0.4 and
// 1.3 kg, with the segments weighted over the prior's spread).
TEST(Identification, LimitCyclingAndSinkingVehiclesKeepTheirSpeeds) {
  const Harness h;
  for (std::uint64_t seed : {1109ULL, 1136ULL}) {
    const CaseResult r = h.run(seed, false);
    SCOPED_TRACE(r.truth.describe());
    ASSERT_TRUE(r.known);
    EXPECT_EQ(r.log_rpms.size(), 3u);
    EXPECT_LT(r.net_sigma_kg, 1.5);
    EXPECT_LE(std::abs(r.net_err_kg), 2.0 * r.net_sigma_kg);
    EXPECT_LE(std::abs(r.x_err_mm), 2.0 * r.x_sigma_mm);
  }
}

// Truth 2123 flies two speeds with the elevator at 6 and 11 deg and very
// quiet means (pitch and elevator to 0.004 deg). At the prior mean the
// covariance of a segment's heave and pitch residuals is nearly singular,
// and the fit trusted that one combination: net buoyancy 4.9 kg off with a
// stated sigma of 1.4 kg (3.6 sigma), CG x 10 mm off (4.3 sigma), and the
// vehicle ended 2 kg heavy after one move. Weighted over the prior's spread:
// net 2.7 +- 1.7 kg, CG x 6.3 +- 3.0 mm (2.1 sigma, the edge of what one
// case in twenty may do), and the move leaves it positive.
TEST(Identification, QuietTwoSpeedLogIsNotOverconfident) {
  const Harness h;
  const CaseResult r = h.run(2123, true);
  SCOPED_TRACE(r.truth.describe());
  ASSERT_TRUE(r.known);
  std::printf("  2123: net err %+.2f kg (sigma %.2f), CG x err %+.2f mm (sigma %.2f), after one move %+.2f kg\n",
              r.net_err_kg, r.net_sigma_kg, r.x_err_mm, r.x_sigma_mm, r.one.min_net_kg);
  EXPECT_LE(std::abs(r.net_err_kg), 2.0 * r.net_sigma_kg);
  EXPECT_LE(std::abs(r.x_err_mm), 2.5 * r.x_sigma_mm);
  ASSERT_TRUE(r.looped);
  EXPECT_GE(r.one.min_net_kg, 0.0);
}

}  // namespace
}  // namespace auv::identification
