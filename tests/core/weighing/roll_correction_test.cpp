#include "weighing/roll_correction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "report_matlab.h"
#include "slocum_test_support.h"

namespace auv {
namespace {

using namespace slocum_test;

double reportHAvg(const double (&mass)[3], const double (&reading)[3], double M) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i) s += report::hArm(mass[i], reading[i], kReportBeta, M);
  return s / 3.0;
}

Eigen::Vector2d gFrom(double h, double beta) { return h * Eigen::Vector2d(std::sin(beta), std::cos(beta)); }

SlocumBallast synthetic(double rails_g, double bow_g) {
  SlocumBallast b;
  b.at(kRailPort) = b.at(kRailStarboard) = rails_g * 1e-3;
  b.at(kForePort) = b.at(kForeStarboard) = bow_g * 1e-3;
  b.at(kAftUpper) = b.at(kAftLower) = 0.200;
  return b;
}

double itemTotal(const SlocumBallast& b) {
  double s = 0.0;
  for (double m : b.item_kg) s += m;
  return s;
}

}  // namespace

TEST(RollCorrection, AppendixBBatteryAngle) {
  const double mass[3] = {0.5, 0.6, 0.7}, reading[3] = {0.10, 0.14, 0.16};
  const double h = reportHAvg(mass, reading, kAppBMassKg);  // 0.0054528 m, as printed
  const SlocumLayout L = layout();
  const RollCorrection rc = correctRoll(L, appendixBAfterTankStep(), kAppBBatteryKg, kAppBMassKg, gFrom(h, kReportBeta));
  ASSERT_EQ(rc.chosen, 0);
  const RollOption& o = rc.best();
  EXPECT_EQ(o.method, RollMethod::BatteryOnly);

  // (a) By hand: the battery must cancel M y_G = M h sin(beta):
  // phi = -asin(M h sin(beta) / (m_b r_b)) = -0.0513793 rad (-2.9438 deg).
  const double phi = -std::asin(kAppBMassKg * h * std::sin(kReportBeta) / (kAppBBatteryKg * 0.0635));
  EXPECT_NEAR(o.battery_angle_rad, phi, 1e-14);
  EXPECT_NEAR(o.battery_angle_rad, -0.0513793, 5e-8);
  EXPECT_NEAR(o.cg_yz_m[0], 0.0, 1e-15);

  // (b) The report prints -0.051334 rad / -2.9412 deg: its posncalc takes
  // -sin(x_b / r_b) where the angle is asin(x_b / r_b).
  const report::PosnCalc p = report::posncalc(h, kReportBeta, kAppBMassKg, kAppBBatteryKg);
  EXPECT_NEAR(p.theta, -0.051334, 5e-7);
  EXPECT_NEAR(p.theta * 180.0 / std::numbers::pi, -2.9412, 5e-5);

  // The h after the battery move is right in the report (its y_b uses the
  // exact sqrt): h cos(beta) - m_b r_b (1 - cos phi) / M = 5.4181 mm. The
  // App. B h-arm list (0.0056666 ...) is built on it, see disk_weights_test.
  EXPECT_NEAR(o.cg_yz_m[1], p.h_out, 1e-15);
  EXPECT_NEAR(o.cg_yz_m[1], h * std::cos(kReportBeta) - kAppBBatteryKg * 0.0635 * (1.0 - std::cos(phi)) / kAppBMassKg,
              1e-15);
  EXPECT_NEAR(o.cg_yz_m[1], 0.0054181, 5e-8);
}

TEST(RollCorrection, AppendixCBatteryAngle) {
  // App. C log: "battery only: -0.031435"; asin gives -0.0314457.
  const double mass[3] = {0.3, 0.4, 0.5}, reading[3] = {0.12, 0.15, 0.18};
  const double h = reportHAvg(mass, reading, kAppCMassKg);
  EXPECT_NEAR(report::posncalc(h, kReportBeta, kAppCMassKg, kAppCBatteryKg).theta, -0.031435, 5e-7);
  SlocumBallast b;
  b.at(kForePort) = 0.062;
  b.at(kForeStarboard) = 0.063;
  b.at(kAftUpper) = b.at(kAftLower) = 0.194;
  const RollCorrection rc = correctRoll(layout(), b, kAppCBatteryKg, kAppCMassKg, gFrom(h, kReportBeta));
  ASSERT_EQ(rc.chosen, 0);
  EXPECT_NEAR(rc.best().battery_angle_rad,
              -std::asin(kAppCMassKg * h * std::sin(kReportBeta) / (kAppCBatteryKg * 0.0635)), 1e-14);
  EXPECT_NEAR(rc.best().battery_angle_rad, -0.0314457, 5e-8);
}

TEST(RollCorrection, AppendixCWingRailAndBottleLogIsTheReportsCgchange) {
  // (b) The App. C log's other battery angles come from cgchange with x/y
  // swapped (x_t = -h cos beta): 0.34157, 0.34148, -0.031509 rad. The
  // printed function cannot run (x_s, x_p undefined); with them zero it
  // gives the logged values to ~3e-5 rad.
  const double mass[3] = {0.3, 0.4, 0.5}, reading[3] = {0.12, 0.15, 0.18};
  const double h = reportHAvg(mass, reading, kAppCMassKg), M = kAppCMassKg, mb = kAppCBatteryKg;
  const report::CgChange wing = report::cgchange(kReportBeta, h, M, 171, 172, 120, 0.11, 0.0);
  EXPECT_NEAR(report::posncalc(wing.h_new, wing.beta_new, M, mb).theta, 0.34157, 5e-5);
  // "Adjusted Port/Starboard Wing Rail Mass: 0.223 / 0.12" (kg, from gram
  // inputs), and 223 g is above the 120 g the rail is said to hold.
  EXPECT_NEAR(wing.m_p_new, 0.223, 1e-12);
  EXPECT_NEAR(wing.m_s_new, 0.120, 1e-12);
  const report::CgChange bow3 = report::cgchange(kReportBeta, h, M, 62, 63, 125, 0.0749, -0.975);
  EXPECT_NEAR(report::posncalc(bow3.h_new, bow3.beta_new, M, mb).theta, 0.34148, 5e-5);
  const report::CgChange bow4 = report::cgchange(wing.beta_new, wing.h_new, M, 62, 63, 125, 0.0749, -0.975);
  EXPECT_NEAR(report::posncalc(bow4.h_new, bow4.beta_new, M, mb).theta, -0.031509, 5e-5);
  // The logged "Adjusted Port Ballast tank mass: 0.125 / starboard 0" is the
  // 4th call's output, which overwrote the 3rd's (port 0, starboard 0.125).
  EXPECT_NEAR(bow4.m_p_new, 0.125, 1e-12);
  EXPECT_NEAR(bow4.m_s_new, 0.0, 1e-12);
  EXPECT_NEAR(bow3.m_p_new, 0.0, 1e-12);
  EXPECT_NEAR(bow3.m_s_new, 0.125, 1e-12);
}

TEST(RollCorrection, WingRailsWhenTheBatteryIsNotEnough) {
  // G 2.9 mm to starboard on a 52 kg glider: M y = 0.1508 kg m. The battery
  // reaches 7.86 * 0.0635 * sin(0.288) = 0.14176 kg m: not enough. All 60 g
  // of the starboard rail go to port (0.060 * 0.22 m = 0.0132 kg m), the
  // battery takes asin(-(0.1508 - 0.0132) / 0.49911) = -0.27932 rad.
  const SlocumLayout L = layout();
  const SlocumBallast now = synthetic(60, 150);
  const double M = 52.0;
  const RollCorrection rc = correctRoll(L, now, 7.86, M, Eigen::Vector2d(0.0029, 0.006));
  EXPECT_FALSE(rc.options[0].feasible);
  ASSERT_EQ(rc.chosen, 1);
  const RollOption& o = rc.best();
  EXPECT_NEAR(o.rail_shift_kg, -0.060, 1e-12);
  EXPECT_NEAR(o.after.at(kRailPort), 0.120, 1e-12);
  EXPECT_NEAR(o.after.at(kRailStarboard), 0.0, 1e-12);
  const double phi = std::asin(-(M * 0.0029 - 0.060 * 0.22) / (7.86 * 0.0635));
  EXPECT_NEAR(o.battery_angle_rad, phi, 1e-12);
  EXPECT_NEAR(phi, -0.27932, 5e-5);
  EXPECT_NEAR(o.cg_yz_m[0], 0.0, 1e-15);
  // The battery rises as it swings: z_G drops by m_b r_b (1 - cos phi) / M.
  EXPECT_NEAR(o.cg_yz_m[1], 0.006 - 7.86 * 0.0635 * (1.0 - std::cos(phi)) / M, 1e-15);
  EXPECT_NEAR(itemTotal(o.after), itemTotal(now), 1e-15);
}

TEST(RollCorrection, BowBottlesWhenTheRailsAreEmpty) {
  // Same G, empty rails: the starboard bow bottle's 150 g go to port
  // (0.150 * 0.08406 m), the battery takes the rest.
  const SlocumLayout L = layout();
  const double span = 2.0 * 0.04203;
  const RollCorrection rc = correctRoll(L, synthetic(0, 150), 7.86, 52.0, Eigen::Vector2d(0.0029, 0.006));
  EXPECT_FALSE(rc.options[1].feasible);
  ASSERT_EQ(rc.chosen, 2);
  EXPECT_NEAR(rc.best().bottle_shift_kg, -0.150, 1e-12);
  EXPECT_NEAR(rc.best().battery_angle_rad, std::asin(-(52.0 * 0.0029 - 0.150 * span) / (7.86 * 0.0635)), 1e-12);
}

TEST(RollCorrection, NothingReachesAndTheBestEffortSaysHowFar) {
  const RollCorrection rc = correctRoll(layout(), synthetic(60, 150), 7.86, 52.0, Eigen::Vector2d(0.005, 0.006));
  EXPECT_EQ(rc.chosen, -1);
  const RollOption& o = rc.best();
  EXPECT_EQ(o.method, RollMethod::RailsAndBottles);
  EXPECT_NEAR(o.battery_angle_rad, -0.288, 1e-12);
  // Residual lateral moment by hand: 0.26 - 0.0132 - 0.150 * 0.08406 - 0.49911 sin(0.288).
  const double rest = 52.0 * 0.005 - 0.060 * 0.22 - 0.150 * 2.0 * 0.04203 - 7.86 * 0.0635 * std::sin(0.288);
  EXPECT_NEAR(o.cg_yz_m[0], rest / 52.0, 1e-12);
  EXPECT_GT(o.cg_yz_m[0], 0.0);
}

TEST(RollCorrection, LateralShiftStopsWhereItStopsHelping) {
  // G 0.1 mm to starboard: the rail option moves only what centres the
  // battery, 52 * 0.0001 / 0.22 = 23.6 g -> 24 g, not the whole 60 g.
  const RollCorrection rc = correctRoll(layout(), synthetic(60, 150), 7.86, 52.0, Eigen::Vector2d(0.0001, 0.006));
  EXPECT_EQ(rc.chosen, 0);
  EXPECT_NEAR(rc.options[1].rail_shift_kg, -0.024, 1e-12);
  EXPECT_NEAR(std::sin(rc.options[1].battery_angle_rad) * 7.86 * 0.0635, -(0.0052 - 0.024 * 0.22), 1e-12);
}

}  // namespace auv
