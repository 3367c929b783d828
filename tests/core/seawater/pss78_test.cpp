#include "seawater/pss78.h"

#include <gtest/gtest.h>

#include "common/input_error.h"

namespace auv::seawater {
namespace {

// UNESCO Tech. Pap. Mar. Sci. 44 p. 9 (as reproduced in CSIRO sw_test.m):
// R, t68, p -> S, published to 6 decimals.
TEST(Pss78, SalinityMatchesUnescoP9Table) {
  EXPECT_NEAR(salinityFromConductivityRatio(1.0, 15, 0, TempScale::IPTS68), 35.0, 0.5e-6);
  EXPECT_NEAR(salinityFromConductivityRatio(1.2, 20, 2000, TempScale::IPTS68), 37.245628, 0.5e-6);
  EXPECT_NEAR(salinityFromConductivityRatio(0.65, 5, 1500, TempScale::IPTS68), 27.995347, 0.5e-6);
}

// Tech. Paper 44 p. 11, SAL78 Fortran check values.
TEST(Pss78, Sal78CheckValueR1888091T40P10000) {
  EXPECT_NEAR(salinityFromConductivityRatio(1.888091, 40, 10000, TempScale::IPTS68), 40.0000,
              0.5e-4);
  EXPECT_NEAR(conductivityRatioFromSalinity(40, 40, 10000, TempScale::IPTS68), 1.888091, 0.5e-6);
}

// Tech. Paper 44 p. 14 (CNDR table, as reproduced in CSIRO sw_test.m):
// S, t68, p -> R, published to 6 decimals.
// The first row is printed there as 0.498088; we assert 0.498008. Reasons:
// python-seawater's cndr docstring (same UNESCO p. 9/14 inputs) prints
// 0.49800825, and the third row (same S and t at 1000 dbar), which matches to
// all 6 digits, is 0.506244 = 0.498008 * Rp(1000 dbar) = 0.498008 * 1.016538;
// 0.498088 would need Rp = 1.016375. So 0.498088 is a transposed digit.
TEST(Pss78, ConductivityRatioMatchesUnescoP14Table) {
  struct Row {
    double s, t68, p, r;
  };
  constexpr Row rows[] = {{25, 0, 0, 0.498008},    {25, 10, 0, 0.654990},
                          {25, 0, 1000, 0.506244}, {25, 10, 1000, 0.662975},
                          {40, 10, 0, 1.000073},   {40, 30, 0, 1.529967}};
  for (const auto& r : rows) {
    EXPECT_NEAR(conductivityRatioFromSalinity(r.s, r.t68, r.p, TempScale::IPTS68), r.r, 0.5e-6)
        << "S=" << r.s << " t68=" << r.t68 << " p=" << r.p;
  }
}

TEST(Pss78, StandardSeawaterConductivityDefinesS35) {
  // C(35, 15 degC IPTS-68, 0) = 42.914 mS/cm is the definition of the scale.
  // The a_i sum to exactly 35, but the rt(t) polynomial equals 1 at 15 degC
  // only to ~1e-8, hence 1e-7 psu and 1e-8 S/m rather than machine precision.
  EXPECT_NEAR(salinityFromConductivity(4.2914, t90FromT68(15.0), 0), 35.0, 1e-7);
  EXPECT_NEAR(conductivityFromSalinity(35, 15, 0, TempScale::IPTS68), 4.2914, 1e-8);
}

TEST(Pss78, ConductivityRoundTripRecoversSalinity) {
  for (double s : {2.0, 5.0, 20.0, 35.0, 42.0})
    for (double t : {-2.0, 0.0, 10.0, 25.0, 40.0})
      for (double p : {0.0, 1000.0, 5000.0, 10000.0}) {
        const double c = conductivityFromSalinity(s, t, p);
        EXPECT_NEAR(salinityFromConductivity(c, t, p), s, 1e-10)
            << "S=" << s << " T=" << t << " p=" << p;
      }
}

TEST(Pss78, InverseRefusesSalinityOutsidePss78Definition) {
  // Below S ~ 0.008 the PSS-78 polynomial has no inverse at all; the scale is
  // defined from 2 psu, so that is where the inverse stops.
  EXPECT_THROW(conductivityFromSalinity(1.0, 10, 0), InputError);
  EXPECT_THROW(salinityFromConductivity(12.0, 10, 0), InputError);
}

}  // namespace
}  // namespace auv::seawater
