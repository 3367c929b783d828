#include "seawater/depth_pressure.h"

#include <gtest/gtest.h>

#include <cmath>

#include "seawater/eos80.h"

namespace auv::seawater {
namespace {

// UNESCO Tech. Pap. Mar. Sci. 44, depth table (as reproduced in CSIRO
// sw_test.m, "Unesco 1983 data p30"): depth [m] to 2 decimals.
TEST(DepthPressure, DepthMatchesUnescoTable) {
  constexpr double lat[4] = {0, 30, 45, 90};
  constexpr double p[3] = {500, 5000, 10000};
  constexpr double depth[3][4] = {{496.65, 496.00, 495.34, 494.03},
                                  {4915.04, 4908.56, 4902.08, 4889.13},
                                  {9725.47, 9712.65, 9699.84, 9674.23}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(depthFromPressure(p[i], lat[j]), depth[i][j], 0.005)
          << "p=" << p[i] << " lat=" << lat[j];
}

// Tech. Paper 44 DEPTH Fortran check value: 9712.653 m at 10000 dbar, 30 deg.
TEST(DepthPressure, DepthFortranCheckValue) {
  EXPECT_NEAR(depthFromPressure(10000, 30), 9712.653, 0.5e-3);
}

TEST(DepthPressure, DefaultLatitudeIs45AndSignOfLatitudeDoesNotMatter) {
  EXPECT_NEAR(depthFromPressure(10000), 9699.84, 0.005);
  EXPECT_DOUBLE_EQ(depthFromPressure(3000, -30), depthFromPressure(3000, 30));
}

TEST(DepthPressure, PressureFromDepthIsTheExactInverse) {
  for (double lat : {0.0, 30.0, 45.0, 63.4, 90.0})
    for (double p : {0.0, 0.5, 10.0, 100.0, 1000.0, 5000.0, 10000.0, 10900.0}) {
      const double z = depthFromPressure(p, lat);
      EXPECT_NEAR(pressureFromDepth(z, lat), p, 1e-8) << "p=" << p << " lat=" << lat;
    }
  // And against the published table: 9712.65 m (rounded to 0.005 m) at 30 deg.
  EXPECT_NEAR(pressureFromDepth(9712.65, 30), 10000.0, 0.006);
}

// Saunders (1981) check value quoted in CSIRO sw_pres.m: 7500.00 dbar for
// 7321.45 m at 30 deg. Both numbers are rounded to 0.005, so the tolerance is
// 0.005 dbar plus 0.005 m * dp/dz (1.025 dbar/m).
TEST(DepthPressure, SaundersCheckValue) {
  EXPECT_NEAR(pressureFromDepthSaunders(7321.45, 30), 7500.00, 0.005 + 0.005 * 1.025);
}

TEST(DepthPressure, SaundersAgreesWithUnescoInverseToBetterThan0p1Percent) {
  for (double lat : {0.0, 45.0, 90.0})
    for (double z : {10.0, 100.0, 1000.0, 5000.0, 10000.0}) {
      const double exact = pressureFromDepth(z, lat);
      EXPECT_LT(std::abs(pressureFromDepthSaunders(z, lat) - exact), 1e-3 * exact)
          << "z=" << z << " lat=" << lat;
    }
}

TEST(DepthPressure, DensityAtDepthReproducesEos80CheckValueThroughDepth) {
  // S=35, t68=25, 10000 dbar -> 1062.53817 (Tech. Paper 44 p. 19), reached via
  // the depth of 10000 dbar at 30 deg rather than via pressure directly.
  const double z = depthFromPressure(10000, 30);
  EXPECT_NEAR(densityAtDepth(35, 25, z, 30, TempScale::IPTS68), 1062.53817, 0.5e-5);
  EXPECT_DOUBLE_EQ(densityAtDepth(35, 10, 0), densityAtSurface(35, 10));
}

}  // namespace
}  // namespace auv::seawater
