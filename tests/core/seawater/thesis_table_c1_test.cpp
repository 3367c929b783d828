// Reproduces Lillemoen (2014) HUGIN thesis, Table C.1 (T = 4 degC, S = 35):
//   no pressure 1027.812 | 0 m 1027.834 | 10 m 1027.880 | 100 m 1028.301 |
//   1000 m 1032.463 kg/m^3
// and the claim in sec. 4.5 that pressure changes density by "only 0.45 %" at
// 1000 m. See docs/decisions/seawater-thesis-table-c1.md for the reading.
#include <gtest/gtest.h>

#include <cmath>

#include "common/units.h"
#include "seawater/seawater.h"

namespace auv::seawater {
namespace {

constexpr double kS = 35.0, kT = 4.0;
constexpr double kRound3 = 0.5e-3;  // the thesis prints 3 decimals

// What the thesis did for the pressure rows: calctool.org depth->pressure is
// p = p_atm + rho g h with rho = 1025 kg/m^3 and g = 9.80665 m/s^2 (ABSOLUTE
// pressure), fed to an EOS-80 calculator that reads 4 degC as IPTS-68.
double thesisPressure_dbar(double depth_m) {
  constexpr double kAtmosphere_Pa = 101325.0;
  return units::paToDbar(kAtmosphere_Pa + 1025.0 * units::g0 * depth_m);
}

TEST(ThesisTableC1, PressureRowsAreEos80AtAbsolutePressureOfA1025Column) {
  struct Row {
    double depth_m, rho;
  };
  for (const Row r : {Row{0, 1027.834}, Row{10, 1027.880}, Row{100, 1028.301},
                      Row{1000, 1032.463}}) {
    EXPECT_NEAR(density(kS, kT, thesisPressure_dbar(r.depth_m), TempScale::IPTS68), r.rho, kRound3)
        << "depth " << r.depth_m << " m";
  }
}

TEST(ThesisTableC1, ZeroMetreRowIsOffByOneAtmosphere) {
  // EOS-80 pressure is sea (gauge) pressure: 0 at the surface.
  const double eosSurface = densityAtSurface(kS, kT, TempScale::IPTS68);
  EXPECT_NEAR(eosSurface, 1027.786, kRound3);
  // The table's 1027.834 is 1 atm (10.1325 dbar) too deep: +0.047 kg/m^3.
  EXPECT_NEAR(1027.834 - eosSurface,
              density(kS, kT, 10.1325, TempScale::IPTS68) - eosSurface, kRound3);
}

// The thesis App. C.3 Matlab code, transcribed as printed (including the
// truncated -0.005724 and the 5.3675e-9 that EOS-80 has as 5.3875e-9). Its
// pure-water part is Tilton & Taylor (1937), not EOS-80's SMOW (Bigg 1967).
double thesisAppC3(double s, double t) {
  const double pure = 1000.0 * (1.0 - (t + 288.9414) / (508929.2 * (t + 68.12963)) *
                                          ((t - 3.9863) * (t - 3.9863)));
  const double a = 0.824493 - 0.0040899 * t + 0.000076438 * t * t - 0.00000082467 * t * t * t +
                   0.0000000053675 * t * t * t * t;
  const double b = -0.005724 + 0.00010227 * t - 0.0000016546 * t * t;
  return pure + a * s + b * std::pow(s, 1.5) + 0.00048314 * s * s;
}

TEST(ThesisTableC1, NoPressureRowIsTheAppendixC3Formula) {
  EXPECT_NEAR(thesisAppC3(kS, kT), 1027.812, kRound3);
}

TEST(ThesisTableC1, NoPressureRowDiffersFromEos80ByThePureWaterFormula) {
  // The whole 0.026 kg/m^3 gap to EOS-80 is the pure-water term (S = 0) plus
  // the truncated S^1.5 coefficient (0.00066e-3 * 35^1.5 = 0.00014).
  const double gap = 1027.812 - densityAtSurface(kS, kT, TempScale::IPTS68);
  const double pureWaterGap = thesisAppC3(0, kT) - densityAtSurface(0, kT, TempScale::IPTS68);
  EXPECT_NEAR(gap, pureWaterGap + 0.00014, kRound3);
  // Tilton & Taylor give g/mL with the 1901 litre (1.000028 dm^3): 1 at the
  // density maximum, where SMOW gives 999.975 kg/m^3 = 999.975 * 1.000028 g/mL.
  EXPECT_DOUBLE_EQ(thesisAppC3(0, 3.9863), 1000.0);
  EXPECT_NEAR(densityAtSurface(0, 3.98, TempScale::IPTS68) * 1.000028, 1000.0, 0.005);
}

TEST(ThesisTableC1, PressureEffectAt1000mIsThe045PercentTheThesisClaims) {
  // The thesis's own numbers: 1032.463 vs 1027.812.
  const double thesisPercent = (1032.463 / 1027.812 - 1.0) * 100.0;
  EXPECT_NEAR(thesisPercent, 0.45, 0.005);
  // Consistent EOS-80 (gauge pressure, UNESCO depth->pressure at 45 deg, the
  // same formula on both sides): 0.453 %. The claim holds to its 2 digits.
  const double ours =
      (densityAtDepth(kS, kT, 1000.0) / densityAtSurface(kS, kT) - 1.0) * 100.0;
  EXPECT_NEAR(ours, 0.45, 0.005);
  EXPECT_NEAR(ours, thesisPercent, 0.001);
}

TEST(ThesisTableC1, FixedDensityColumnUnderestimatesPressureAt1000m) {
  // rho g h with 1025 kg/m^3 gives 1005.2 dbar gauge; the UNESCO integral of
  // the real (compressed, 1028-1032 kg/m^3) column with latitude gravity
  // gives 1010.6 dbar at 45 deg: 0.54 % more, worth 0.025 kg/m^3 here.
  const double fixedColumn = thesisPressure_dbar(1000) - 10.1325;
  const double unesco = pressureFromDepth(1000, 45);
  EXPECT_NEAR(fixedColumn, 1005.18, 0.005);
  EXPECT_NEAR(unesco / fixedColumn - 1.0, 0.0054, 0.0002);
}

}  // namespace
}  // namespace auv::seawater
