#include "seawater/eos80.h"

#include <gtest/gtest.h>

#include <cmath>

namespace auv::seawater {
namespace {

// UNESCO Tech. Pap. Mar. Sci. 44 (Fofonoff & Millard 1983), p. 19: EOS-80
// check values (from Unesco Tech. Pap. 36/38). t is IPTS-68, p in BAR.
struct Eos80Check {
  double s, t68, p_bar, rho, k_bar;
};
constexpr Eos80Check kUnesco44p19[] = {
    {0, 5, 0, 999.96675, 20337.80375},      {0, 5, 1000, 1044.12802, 23643.52599},
    {0, 25, 0, 997.04796, 22100.72106},     {0, 25, 1000, 1037.90204, 25405.09717},
    {35, 5, 0, 1027.67547, 22185.93358},    {35, 5, 1000, 1069.48914, 25577.49819},
    {35, 25, 0, 1023.34306, 23726.34949},   {35, 25, 1000, 1062.53817, 27108.94504},
};
// Published to 5 decimals: agreement means within half a unit of the last digit.
constexpr double kHalfUlp5 = 0.5e-5;

TEST(Eos80, DensityMatchesUnescoCheckTableToAllPublishedDigits) {
  for (const auto& c : kUnesco44p19) {
    EXPECT_NEAR(density(c.s, c.t68, c.p_bar * 10.0, TempScale::IPTS68), c.rho, kHalfUlp5)
        << "S=" << c.s << " t68=" << c.t68 << " p=" << c.p_bar << " bar";
  }
}

TEST(Eos80, SecantBulkModulusInBarMatchesUnescoCheckTable) {
  for (const auto& c : kUnesco44p19) {
    EXPECT_NEAR(secantBulkModulus(c.s, c.t68, c.p_bar * 10.0, TempScale::IPTS68), c.k_bar,
                kHalfUlp5)
        << "S=" << c.s << " t68=" << c.t68 << " p=" << c.p_bar << " bar";
  }
}

TEST(Eos80, SurfaceDensityIsTheZeroPressureRowOfTheTable) {
  EXPECT_NEAR(densityAtSurface(0, 5, TempScale::IPTS68), 999.96675, kHalfUlp5);
  EXPECT_NEAR(densityAtSurface(35, 25, TempScale::IPTS68), 1023.34306, kHalfUlp5);
  EXPECT_DOUBLE_EQ(density(35, 12, 0), densityAtSurface(35, 12));
}

// Tech. Paper 44 p. 20, SVAN check value: sigma = 59.82037 kg/m^3 at S=40,
// t68=40, p=10000 dbar. The paper's value came from single-precision Fortran;
// the double-precision EOS-80 gives 1059.8203768, i.e. 1059.82038 rounded,
// one unit off in the 5th decimal. We therefore allow 1e-5, not 0.5e-5.
TEST(Eos80, SvanCheckValueS40T40P10000) {
  EXPECT_NEAR(density(40, 40, 10000, TempScale::IPTS68), 1059.82037, 1e-5);
}

TEST(Eos80, Its90InputIsConvertedToIpts68) {
  for (const auto& c : kUnesco44p19) {
    EXPECT_NEAR(density(c.s, t90FromT68(c.t68), c.p_bar * 10.0), c.rho, kHalfUlp5);
  }
  // 25 degC ITS-90 is 25.006 degC IPTS-68: the scales must not be confused.
  const double d90 = density(35, 25, 0, TempScale::ITS90);
  const double d68 = density(35, 25, 0, TempScale::IPTS68);
  EXPECT_NEAR(d90, density(35, 25.006, 0, TempScale::IPTS68), 1e-9);
  EXPECT_GT(std::abs(d90 - d68), 1e-3);
}

// Independent physical oracle: pure water (Bigg 1967 SMOW) is densest at
// 3.98 degC, 999.975 kg/m^3.
TEST(Eos80, PureWaterIsDensestNear398Celsius) {
  double lo = 0.0, hi = 8.0;
  for (int i = 0; i < 100; ++i) {
    const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
    if (densityAtSurface(0, m1, TempScale::IPTS68) < densityAtSurface(0, m2, TempScale::IPTS68))
      lo = m1;
    else
      hi = m2;
  }
  EXPECT_NEAR(lo, 3.98, 0.005);
  EXPECT_NEAR(densityAtSurface(0, lo, TempScale::IPTS68), 999.975, 0.0005);
}

}  // namespace
}  // namespace auv::seawater
