#include "weighing/tank_weighing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.h"
#include "slocum_test_support.h"

namespace auv {
namespace {

using slocum_test::layout;
using slocum_test::profile;

constexpr double kGram = 1e-3;

TankReadings appendixB() {
  TankReadings r;
  r.dry_mass_kg = 52.2;
  r.bow_scale_kg = 0.650;
  r.aft_scale_kg = 0.520;
  r.tank = {1000.0, 18.5};
  r.target = {1026.0, 3.5};
  return r;
}

TankReadings appendixC() {
  TankReadings r;
  r.dry_mass_kg = 50.0;
  r.bow_scale_kg = 0.550;
  r.aft_scale_kg = 0.490;
  r.tank = {1000.0, 18.0};
  r.target = {1025.0, 3.0};
  return r;
}

HullModel aluminium() {
  HullModel h;
  h.thermal_expansion_per_degC = 7e-5;  // report's expans_coeff
  return h;
}

const ScaleStations kSymmetric{0.5, -0.5};

SlocumBallast withBottles(double fp, double fs, double au, double al) {
  SlocumBallast b;
  b.at(kForePort) = fp;
  b.at(kForeStarboard) = fs;
  b.at(kAftUpper) = au;
  b.at(kAftLower) = al;
  return b;
}

std::string fieldOf(const TankReadings& r, const ScaleStations& s = kSymmetric) {
  try {
    tankBuoyancy(r, aluminium(), s);
  } catch (const InputError& e) {
    return e.field();
  }
  return "no error";
}

}  // namespace

TEST(TankWeighing, AppendixBPrintedNumbers) {
  // Report App. B prints (5 significant digits): V_tank 0.05103, m_tank 51.03,
  // V_target 0.050976, m_target 52.3018, change 101.8054 g, bow -14.0973 g,
  // aft 115.9027 g. These §4.1 formulas are right, so our values must match.
  const TankBuoyancy t = tankBuoyancy(appendixB(), aluminium(), kSymmetric);
  EXPECT_NEAR(t.scale_total_kg, 1.170, 1e-12);
  EXPECT_NEAR(t.tank_neutral_mass_kg, 51.03, 1e-12);
  EXPECT_NEAR(t.volume_tank_m3, 0.05103, 1e-12);
  EXPECT_NEAR(t.volume_target_m3, 0.050976, 5e-7);
  EXPECT_NEAR(t.target_neutral_mass_kg, 52.3018, 5e-5);
  EXPECT_NEAR(t.mass_change_kg / kGram, 101.8054, 5e-4);
  EXPECT_NEAR(t.bow_change_kg / kGram, -14.0973, 5e-4);
  EXPECT_NEAR(t.aft_change_kg / kGram, 115.9027, 5e-4);
  // Independent hand value: 51.03 * (1 - 15 * 7e-5) * 1026 / 1000 kg.
  EXPECT_NEAR(t.target_neutral_mass_kg, 0.05103 * 0.99895 * 1026.0, 1e-12);
  // Level: both scales share the apparent weight (1170 + 101.8054) / 2.
  EXPECT_NEAR(t.level_bow_scale_kg, t.level_aft_scale_kg, 1e-15);
}

TEST(TankWeighing, AppendixCPrintedNumbers) {
  // App. C log: 48.96 kg, 0.04896 m3, 0.048909 m3, 50.1313 kg, 131.3068 g,
  // aft 95.6534 g, bow 35.6534 g.
  const TankBuoyancy t = tankBuoyancy(appendixC(), aluminium(), kSymmetric);
  EXPECT_NEAR(t.tank_neutral_mass_kg, 48.96, 1e-12);
  EXPECT_NEAR(t.volume_tank_m3, 0.04896, 1e-12);
  EXPECT_NEAR(t.volume_target_m3, 0.048909, 5e-7);
  EXPECT_NEAR(t.target_neutral_mass_kg, 50.1313, 5e-5);
  EXPECT_NEAR(t.mass_change_kg / kGram, 131.3068, 5e-4);
  EXPECT_NEAR(t.aft_change_kg / kGram, 95.6534, 5e-4);
  EXPECT_NEAR(t.bow_change_kg / kGram, 35.6534, 5e-4);
}

TEST(TankWeighing, ReportPairSplitReproducedButWeKeepTheExistingSplit) {
  // (b) Report: bow_new = (port + star + bow_change) / 2 = 151.9513 g and
  // aft_new = (upper + lower + aft_change) / 2 = 287.9513 g (App. B);
  // 62.8267 / 194.3267 g (App. C). Reproduced from the same numbers:
  const TankBuoyancy b = tankBuoyancy(appendixB(), aluminium(), kSymmetric);
  EXPECT_NEAR((208.0 + 110.0 + b.bow_change_kg / kGram) / 2.0, 151.9513, 5e-4);
  EXPECT_NEAR((200.0 + 260.0 + b.aft_change_kg / kGram) / 2.0, 287.9513, 5e-4);
  const TankBuoyancy c = tankBuoyancy(appendixC(), aluminium(), kSymmetric);
  EXPECT_NEAR((60.0 + 30.0 + c.bow_change_kg / kGram) / 2.0, 62.8267, 5e-4);
  EXPECT_NEAR((293.0 + 0.0 + c.aft_change_kg / kGram) / 2.0, 194.3267, 5e-4);

  // (a) Ours, by hand: total rounded down to 101 g; level readings
  // (1170 + 101) / 2 = 635.5 g each -> bow -14.5 g (whole grams: -15, ties
  // away from zero), aft +116 g; each bottle of a pair takes half, keeping
  // the port/starboard and upper/lower differences of the earlier trim.
  const BottleStep s = planBottleStep(b, appendixB(), withBottles(0.208, 0.110, 0.200, 0.260), layout());
  EXPECT_NEAR(s.total_change_kg, 0.101, 1e-12);
  EXPECT_NEAR(s.bow_change_kg, -0.015, 1e-12);
  EXPECT_NEAR(s.aft_change_kg, 0.116, 1e-12);
  EXPECT_NEAR(s.after.at(kForePort), 0.200, 1e-12);
  EXPECT_NEAR(s.after.at(kForeStarboard), 0.103, 1e-12);
  EXPECT_NEAR(s.after.at(kAftUpper), 0.258, 1e-12);
  EXPECT_NEAR(s.after.at(kAftLower), 0.318, 1e-12);
  EXPECT_NEAR(s.after.at(kForeStarboard) - s.after.at(kForePort), 0.110 - 0.208 + 0.001, 1e-12);
  // Never heavy: neutral 52.301805 kg, glider 52.301 kg.
  EXPECT_NEAR(s.net_buoyancy_after_kg, b.target_neutral_mass_kg - 52.301, 1e-12);
  EXPECT_GE(s.net_buoyancy_after_kg, 0.0);
  EXPECT_LT(s.net_buoyancy_after_kg, 0.001);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(TankWeighing, ExpectedScaleReadingsMatchTheSessions) {
  // Report: after the operator set 288/288/152/152 g (App. B) the scales
  // "should read approximately 636 g" and the glider 52.302 kg; App. C set
  // 194/194/62/63 g -> 585 g and 50.13 kg. With the scales over the bottles
  // each change lands on its own scale.
  TankReadings b = appendixB();
  b = withAddedMass(b, kSymmetric, 0.152 + 0.152 - 0.208 - 0.110, 0.5);
  b = withAddedMass(b, kSymmetric, 0.288 + 0.288 - 0.200 - 0.260, -0.5);
  EXPECT_NEAR(b.dry_mass_kg, 52.302, 1e-12);
  EXPECT_NEAR(b.bow_scale_kg, 0.636, 1e-12);
  EXPECT_NEAR(b.aft_scale_kg, 0.636, 1e-12);
  // The report's expected_scale = (new_mass - tank_buoy) / 2 is the same number.
  EXPECT_NEAR((52.302 - 51.03) / 2.0, 0.636, 1e-12);

  TankReadings c = appendixC();
  c = withAddedMass(c, kSymmetric, 0.062 + 0.063 - 0.060 - 0.030, 0.5);
  c = withAddedMass(c, kSymmetric, 0.194 + 0.194 - 0.293 - 0.0, -0.5);
  EXPECT_NEAR(c.dry_mass_kg, 50.13, 1e-12);
  EXPECT_NEAR(c.bow_scale_kg, 0.585, 1e-12);
  EXPECT_NEAR(c.aft_scale_kg, 0.585, 1e-12);
}

TEST(TankWeighing, VolumeDoesNotDependOnWhereBallastWasAdded) {
  // Conservation: adding mass inside the hull changes dry mass and readings
  // by the same amount, so the displaced volume is unchanged.
  const TankReadings r = withAddedMass(appendixB(), kSymmetric, 0.123, 0.2);
  const TankBuoyancy a = tankBuoyancy(appendixB(), aluminium(), kSymmetric);
  const TankBuoyancy b = tankBuoyancy(r, aluminium(), kSymmetric);
  EXPECT_NEAR(a.volume_tank_m3, b.volume_tank_m3, 1e-15);
  EXPECT_NEAR(b.mass_change_kg, a.mass_change_kg - 0.123, 1e-12);
  // Lever rule: 0.123 kg at x = 0.2 between 0.5 and -0.5 puts 70 % on the bow scale.
  EXPECT_NEAR(r.bow_scale_kg - 0.650, 0.7 * 0.123, 1e-12);
}

TEST(TankWeighing, AsymmetricStationsUseTheLeverRule) {
  // Bow scale 0.6 m ahead of CB, aft 0.4 m behind: level means the bow scale
  // carries 0.4 / 1.0 of the apparent weight; CG x from moments about CB.
  const ScaleStations s{0.6, -0.4};
  const TankBuoyancy t = tankBuoyancy(appendixB(), aluminium(), s);
  const double apparent = 1.170 + t.mass_change_kg;
  EXPECT_NEAR(t.level_bow_scale_kg, 0.4 * apparent, 1e-12);
  EXPECT_NEAR(t.level_aft_scale_kg, 0.6 * apparent, 1e-12);
  EXPECT_NEAR(t.cg_x_from_cb_m, (0.650 * 0.6 - 0.520 * 0.4) / 52.2, 1e-15);
}

TEST(TankWeighing, CompressibilityShrinksTheTargetVolume) {
  TankReadings r = appendixB();
  r.target_pressure_dbar = 100.0;
  HullModel h = aluminium();
  h.compressibility_per_dbar = 3e-6;
  const TankBuoyancy t = tankBuoyancy(r, h, kSymmetric);
  EXPECT_NEAR(t.volume_target_m3, 0.05103 * 0.99895 * (1.0 - 3e-4), 1e-15);
}

TEST(TankWeighing, RoundsDownSoTheGliderNeverEndsHeavy) {
  // Sweep the dry mass through a few grams: whatever the fraction of a gram,
  // the planned glider is never heavier than neutral and less than 1 g light.
  for (int k = 0; k < 200; ++k) {
    TankReadings r = appendixB();
    r.dry_mass_kg = 52.2 + 0.0001234 * k;
    r.bow_scale_kg = 0.650 + 0.0000617 * k;
    const TankBuoyancy t = tankBuoyancy(r, aluminium(), kSymmetric);
    const BottleStep s = planBottleStep(t, r, withBottles(0.2, 0.2, 0.2, 0.2), layout());
    EXPECT_GE(s.net_buoyancy_after_kg, -1e-12) << k;
    EXPECT_LT(s.net_buoyancy_after_kg, 0.001 + 1e-12) << k;
    EXPECT_NEAR(s.total_change_kg, s.bow_change_kg + s.aft_change_kg, 1e-12);
  }
}

TEST(TankWeighing, FullBottleSpillsIntoItsPartnerThenTheOtherPair) {
  // Same total as App. B but nose-light: level readings (1170 + 101) / 2 =
  // 635.5 g -> bow +135.5 g (+136 in whole grams), aft -35 g.
  TankReadings r = appendixB();
  r.bow_scale_kg = 0.500;
  r.aft_scale_kg = 0.670;
  const TankBuoyancy t = tankBuoyancy(r, aluminium(), kSymmetric);
  BottleStep s = planBottleStep(t, r, withBottles(0.449, 0.100, 0.100, 0.100), layout());
  EXPECT_NEAR(s.bow_change_kg, 0.136, 1e-12);
  EXPECT_NEAR(s.aft_change_kg, -0.035, 1e-12);
  // fore_port can take 1 g of its 68 g share; fore_starboard takes the rest.
  EXPECT_NEAR(s.after.at(kForePort), 0.450, 1e-12);
  EXPECT_NEAR(s.after.at(kForeStarboard), 0.100 + 0.135, 1e-12);
  EXPECT_TRUE(s.warnings.empty());

  // Both bow bottles full: the aft pair takes the whole 101 g so the
  // buoyancy is still right, with a warning that it will not float level.
  s = planBottleStep(t, r, withBottles(0.450, 0.450, 0.100, 0.100), layout());
  EXPECT_NEAR(s.bow_change_kg, 0.0, 1e-12);
  EXPECT_NEAR(s.aft_change_kg, 0.101, 1e-12);
  EXPECT_GE(s.net_buoyancy_after_kg, 0.0);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("level"), std::string::npos);
}

TEST(TankWeighing, EmptyBottlesCannotMakeItLighterAndSaySo) {
  // Target water fresh and warm: the glider must lose ~1.2 kg it cannot lose.
  TankReadings r = appendixB();
  r.target = {1000.0, 18.5};
  const TankBuoyancy t = tankBuoyancy(r, aluminium(), kSymmetric);
  EXPECT_NEAR(t.mass_change_kg, -1.170, 1e-9);
  const BottleStep s = planBottleStep(t, r, withBottles(0.05, 0.05, 0.05, 0.05), layout());
  EXPECT_NEAR(s.total_change_kg, -0.200, 1e-12);
  EXPECT_LT(s.net_buoyancy_after_kg, 0.0);
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings.back().find("HEAVY"), std::string::npos);
}

TEST(TankWeighing, BadReadingsNameTheFileField) {
  TankReadings r = appendixB();
  r.bow_scale_kg = -0.1;
  EXPECT_EQ(fieldOf(r), "tank.bow_scale_g");
  r = appendixB();
  r.aft_scale_kg = NAN;
  EXPECT_EQ(fieldOf(r), "tank.aft_scale_g");
  r = appendixB();
  r.tank.density_kgm3 = 1.0;  // typed g/cm3
  EXPECT_EQ(fieldOf(r), "tank.density_kgm3");
  r = appendixB();
  r.target.temperature_degC = 300.0;
  EXPECT_EQ(fieldOf(r), "target.temperature_degC");
  r = appendixB();
  r.bow_scale_kg = 60.0;  // typed kg where grams were meant: more than the glider
  EXPECT_EQ(fieldOf(r), "tank.bow_scale_g");
  EXPECT_EQ(fieldOf(appendixB(), ScaleStations{-0.1, -0.5}), "slocum.ballast_bottles");
}

}  // namespace auv
