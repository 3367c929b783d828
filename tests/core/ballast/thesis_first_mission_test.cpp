// Thesis first-mission oracles (Lillemoen 2014): Table F.1 inputs, Table G.1
// (continuous shares) and Table G.2 (mapped pieces), reproduced with the
// thesis's own method, then beaten by the exact solver.
#include <gtest/gtest.h>

#include <cmath>

#include "ballast/ballast_solver.h"
#include "ballast/thesis_greedy.h"
#include "hugin_thesis_cases.h"

namespace auv {
namespace {

using testing::RopeOrigin;
using testing::tableF1;
using testing::thesisProblem;

// Table G.1 and G.2 rows: FS, FP, AS, AP in kg (thesis App. G.1).
const double kTableG1[6][4] = {{0.1, 0.1, 0.3, 0.3},   {11.3, 11.3, 23.6, 23.6}, {10.5, 10.5, 24.3, 24.3},
                               {11.5, 11.0, 24.0, 23.1}, {10.5, 10.5, 24.3, 24.3}, {12.0, 12.0, 22.8, 22.8}};
const double kTableG2[6][4] = {{0, 0, 0, 0},           {10.8, 10.8, 22.8, 22.8}, {9.6, 9.6, 24.0, 24.0},
                               {10.8, 10.8, 24.0, 22.8}, {9.6, 9.6, 24.0, 24.0},   {12.0, 12.0, 22.8, 22.8}};
const double kTableG1Total[6] = {0.8, 69.8, 69.6, 69.6, 69.6, 69.6};
const std::size_t kCase4 = 3;

// A Table G.2 row as a move with the HUGIN kit (1.2, 2.4, 4.8), largest first.
std::vector<std::vector<int>> tableMove(const double row[4]) {
  std::vector<std::vector<int>> d(4, std::vector<int>(3, 0));
  for (std::size_t p = 0; p < 4; ++p) {
    long units = std::lround(row[p] / 1.2);
    EXPECT_NEAR(static_cast<double>(units) * 1.2, row[p], 1e-9) << "Table G.2 entry is not a multiple of 1.2 kg";
    d[p][2] = static_cast<int>(units / 4);
    units %= 4;
    d[p][1] = static_cast<int>(units / 2);
    d[p][0] = static_cast<int>(units % 2);
  }
  return d;
}

TEST(ThesisRopes, ProfileVolumeMatchesAppendixA) {
  // App. A: V = (1498 + 65) / 1024.8 = 1.5252 m^3 (printed to 4 decimals).
  EXPECT_NEAR(testing::hugin().hull.volume_m3, testing::kThesisVolume, 5e-5);
}

TEST(ThesisRopes, CaseOneHasNoErrorOnlyWithRopesAboutTheCb) {
  // Case 1 is "no ballast errors" with equal readings: the CG sits midway
  // between the ropes. Only ropes centred on the CB make that true; centred
  // on the body origin the same readings put the CG 157.8 mm ahead of the CB.
  const auto& c1 = tableF1()[0];
  const Eigen::Vector3d cb = testing::hugin().cb_m;
  const MassProperties about_cb = testing::thesisWeighing(c1, RopeOrigin::AboutCb);
  EXPECT_NEAR(about_cb.cg_m.x(), cb.x(), 1e-12);
  EXPECT_NEAR(about_cb.cg_m.y(), cb.y(), 1e-12);
  const BallastSolution none = evaluateMove(thesisProblem(c1), std::vector<std::vector<int>>(4, {0, 0, 0}));
  EXPECT_LT(std::abs(none.pitch_deg), 0.5);  // what is left is the net-buoyancy moment of 0.82 kg
  EXPECT_LT(std::abs(none.roll_deg), 0.01);

  const MassProperties about_origin = testing::thesisWeighing(c1, RopeOrigin::AboutOrigin);
  EXPECT_NEAR(about_origin.cg_m.x() - cb.x(), 0.1578, 1e-12);
  const BallastSolution off =
      evaluateMove(thesisProblem(c1, RopeOrigin::AboutOrigin), std::vector<std::vector<int>>(4, {0, 0, 0}));
  // atan(157.8 / 20): the vehicle would hang nose down at about 83 degrees.
  EXPECT_LT(off.pitch_deg, -80.0);
  // ... and with the side ropes about the centre line, the CB's 0.57 mm to
  // starboard alone would roll it by 1.6 degrees: not "no error" either.
  const BallastSolution centre_line = evaluateMove(thesisProblem(c1, RopeOrigin::CbStationOnCentreLine),
                                                   std::vector<std::vector<int>>(4, {0, 0, 0}));
  EXPECT_LT(centre_line.roll_deg, -1.5);
}

TEST(ThesisRopes, CaseTwoAndThreeSharesOnlyFitRopesAboutTheCb) {
  // Table G.1 case 3 (10.5 / 24.3 kg) follows from a CG 32.0 mm ahead of the
  // CB; with origin-centred ropes the thesis's own equations give 6.9 kg fore.
  const ThesisAdjustment cb = thesisAdjustment(thesisProblem(tableF1()[2], RopeOrigin::AboutCb));
  const ThesisAdjustment origin = thesisAdjustment(thesisProblem(tableF1()[2], RopeOrigin::AboutOrigin));
  EXPECT_NEAR(cb.continuous_kg[0], 10.5, 0.05);
  EXPECT_GT(std::abs(origin.continuous_kg[0] - 10.5), 3.0);
}

TEST(ThesisFirstMission, RequiredMassIs69_6kg) {
  // §7.1: "the required ballast adjustment to make the vehicle neutrally
  // buoyant is 69.6 kg" for 1498 kg at 4 degC, 35 ppt.
  const ThesisAdjustment a = thesisAdjustment(thesisProblem(tableF1()[1]));
  EXPECT_NEAR(a.required_kg, 69.6, 0.05);
  EXPECT_NEAR(a.required_kg, 1027.812 * 1.5252 - 1498.0, 1e-9);
}

TEST(ThesisFirstMission, CaseSplitFollowsSection541) {
  const int expected[6] = {1, 1, 2, 3, 4, 4};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(thesisAdjustment(thesisProblem(tableF1()[i])).alternative, expected[i]) << tableF1()[i].name;
  }
}

TEST(ThesisFirstMission, TableG1ContinuousShares) {
  // Printed to 0.1 kg, so each share must round to the printed value (+-0.05).
  // Case 4 is the exception, see the next test.
  for (std::size_t i = 0; i < 6; ++i) {
    if (i == kCase4) continue;
    const ThesisAdjustment a = thesisAdjustment(thesisProblem(tableF1()[i]));
    double total = 0.0;
    for (std::size_t p = 0; p < 4; ++p) {
      EXPECT_NEAR(a.continuous_kg[p], kTableG1[i][p], 0.05 + 1e-9) << tableF1()[i].name << " point " << p;
      total += std::round(a.continuous_kg[p] * 10.0) / 10.0;
    }
    // The Total column is the sum of the rounded shares (69.8 in case 2).
    EXPECT_NEAR(total, kTableG1Total[i], 1e-9) << tableF1()[i].name;
  }
}

TEST(ThesisFirstMission, TableG1CaseFourOnlyForeAftSplitReproduced) {
  // Case 4 (CG 2.67 mm to starboard): the thesis adds more to starboard
  // (11.5/11.0, 24.0/23.1), which moves the CG further to starboard, by about
  // 2.4 times what eq. 5.9 asks for. eq. 5.9 with the printed sign (CB - CG)
  // puts more to port. We keep the equations and reproduce what they fix
  // unambiguously: the fore/aft split (eq. 5.12) and the total.
  const ThesisAdjustment a = thesisAdjustment(thesisProblem(tableF1()[kCase4]));
  const double fore = a.continuous_kg[0] + a.continuous_kg[1], aft = a.continuous_kg[2] + a.continuous_kg[3];
  EXPECT_NEAR(fore, kTableG1[kCase4][0] + kTableG1[kCase4][1], 0.1);
  EXPECT_NEAR(aft, kTableG1[kCase4][2] + kTableG1[kCase4][3], 0.1);
  EXPECT_NEAR(fore + aft, 69.6, 0.05);
  // Physically right direction: port (FP, AP) gets more than starboard.
  EXPECT_GT(a.continuous_kg[1], a.continuous_kg[0]);
  EXPECT_GT(a.continuous_kg[3], a.continuous_kg[2]);
  // and by eq. 5.9: sum(m y) = m_dif (y_CB - y_CG)
  double my = 0.0;
  for (std::size_t p = 0; p < 4; ++p) my += a.continuous_kg[p] * testing::hugin().points[p].position_m.y();
  EXPECT_NEAR(my, a.required_kg * a.cg_shift_m.y(), 1e-9);
}

TEST(ThesisFirstMission, TableG2MappedPiecesReproducedExactly) {
  for (std::size_t i = 0; i < 6; ++i) {
    if (i == kCase4) continue;
    const BallastProblem p = thesisProblem(tableF1()[i]);
    const BallastSolution g = thesisGreedyMapping(p);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(g.add_kg[k], kTableG2[i][k], 1e-9) << tableF1()[i].name;
    // "a little less than 69.6 kg is added in all cases" (§7.1): never negative
    EXPECT_GE(g.net_buoyancy_kg, 0.0) << tableF1()[i].name;
  }
  // Case 5b needs the rounding to 0.1 kg before eq. 5.22: floor(11.987 / 1.2)
  // would give 10.8 kg, the table says 12.0 kg.
  const ThesisAdjustment b5 = thesisAdjustment(thesisProblem(tableF1()[5]));
  EXPECT_LT(b5.continuous_kg[0], 12.0);
  EXPECT_NEAR(b5.mapped_kg[0], 12.0, 1e-9);
}

TEST(ThesisFirstMission, TableG2CaseFourFromOurShares) {
  // Our case-4 shares (11.16, 11.35, 23.36, 23.75) map to 10.8/10.8/22.8/22.8;
  // the thesis's own (starboard-heavy) shares mapped to 10.8/10.8/24.0/22.8.
  const BallastSolution g = thesisGreedyMapping(thesisProblem(tableF1()[kCase4]));
  const double ours[4] = {10.8, 10.8, 22.8, 22.8};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(g.add_kg[k], ours[k], 1e-9);
}

TEST(ThesisFirstMission, ExactSolverBeatsTheMappedTable) {
  // For every case: net buoyancy in [0, 1.2] kg and a CG-CB offset no worse
  // than the thesis's Table G.2 move, in x and as a horizontal distance; in y
  // no worse except where the thesis left the buoyancy band (see below).
  int worse_in_y = 0;
  for (std::size_t i = 0; i < 6; ++i) {
    const BallastProblem p = thesisProblem(tableF1()[i]);
    const BallastSolution thesis = evaluateMove(p, tableMove(kTableG2[i]));
    const BallastSolution exact = solveBallast(p);
    const Eigen::Vector2d t_off = (thesis.cg_m - p.cb_m).head<2>(), e_off = (exact.cg_m - p.cb_m).head<2>();
    SCOPED_TRACE(tableF1()[i].name);
    EXPECT_GE(exact.net_buoyancy_kg, 0.0);
    EXPECT_LE(exact.net_buoyancy_kg, 1.2);
    EXPECT_TRUE(exact.buoyancy_in_band);
    EXPECT_LE(std::abs(e_off.x()), std::abs(t_off.x()) + 1e-12);
    EXPECT_LE(e_off.norm(), t_off.norm() + 1e-12);
    EXPECT_LE(std::abs(exact.pitch_deg), std::abs(thesis.pitch_deg) + 1e-9);
    if (std::abs(e_off.y()) > std::abs(t_off.y())) {
      ++worse_in_y;
      EXPECT_FALSE(thesis.buoyancy_in_band);
      // The thesis added 67.2 kg and left 2.42 kg of positive buoyancy. In
      // band the kit allows only 69.6 kg (58 x 1.2 kg): then port minus
      // starboard is an even number of 1.2 kg units, so sum(m y) is a
      // multiple of 0.78 kg m, and the least |y offset| is that of sum(m y)=0:
      // |69.6 kg * y_CB| / W = 0.0253 mm (the thesis's 0.0245 mm came from
      // adding less mass, i.e. from breaking priority 1). We reach it.
      const double W = p.vehicle.mass_kg + 69.6;
      ASSERT_NEAR(p.displaced_mass_kg - W, exact.net_buoyancy_kg, 1e-9);
      const double least_y = 69.6 * p.cb_m.y() / W;
      EXPECT_NEAR(std::abs(e_off.y()), least_y, 1e-9);
      EXPECT_LT(std::abs(e_off.y()) - std::abs(t_off.y()), 1e-6);  // under a micrometre
    }
  }
  EXPECT_EQ(worse_in_y, 2);  // cases 2 and 3
}

TEST(ThesisFirstMission, CaseOneNeedsNothing) {
  // 0.82 kg light: any piece (>= 1.2 kg) would make the vehicle heavy.
  const BallastSolution s = solveBallast(thesisProblem(tableF1()[0]));
  for (const auto& row : s.delta)
    for (int d : row) EXPECT_EQ(d, 0);
  EXPECT_TRUE(s.buoyancy_in_band && s.pitch_in_band && s.roll_in_band);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(ThesisFirstMission, CaseThreePitchIsOutOfReachAndSaysSo) {
  // CG 32 mm ahead of the CB with BG 20 mm: even 69.6 kg all aft (capacity
  // 40 kg per point) cannot bring it back, so the solver must say that no
  // extra piece size would help, and put the mass as far aft as it can.
  const BallastSolution s = solveBallast(thesisProblem(tableF1()[2]));
  EXPECT_NEAR(s.add_kg[0] + s.add_kg[1], 0.0, 1e-9);
  EXPECT_NEAR(s.add_kg[2] + s.add_kg[3], 69.6, 1e-9);
  EXPECT_FALSE(s.pitch_in_band);
  bool said = false;
  for (const auto& w : s.warnings) said |= w.find("pitch band") != std::string::npos &&
                                          w.find("out of reach whatever the piece sizes") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(ThesisFirstMission, OptionalHalfKiloPieceReachesTheBands) {
  // §8.1: a 0.5 kg piece "will fine tune the ballasting". With it the exact
  // solver meets pitch and roll in cases 2, 4 and 5b (the others are out of
  // reach with 40 kg per point), and the plain kit's warning names a piece.
  for (std::size_t i : {1u, 3u, 5u}) {
    BallastProblem p = thesisProblem(tableF1()[i]);
    const BallastSolution plain = solveBallast(p);
    EXPECT_FALSE(plain.pitch_in_band && plain.roll_in_band) << tableF1()[i].name;
    bool named = false;
    for (const auto& w : plain.warnings) named |= w.find("piece would reach it") != std::string::npos;
    EXPECT_TRUE(named) << tableF1()[i].name;
    p.piece_sizes_kg = {0.5, 1.2, 2.4, 4.8};
    const BallastSolution fine = solveBallast(p);
    EXPECT_TRUE(fine.buoyancy_in_band && fine.pitch_in_band && fine.roll_in_band) << tableF1()[i].name;
  }
}

}  // namespace
}  // namespace auv
