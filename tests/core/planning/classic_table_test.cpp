// The classic policy against the thesis's own test of its pre-mission mode:
// Table F.2's deviations on the vehicle of App. G.2 (10.8, 10.8, 22.8,
// 22.8 kg installed) must give Table G.3's mapped adjustments. Cases the
// printed code and table cannot produce are pinned to what App. E.2 says
// (docs/decisions/planning-classic-table.md).
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "planning/classic_table.h"

using namespace auv;

namespace {

struct Case {
  std::string name;
  double depth, pitch, roll;   // Table F.2 deviations
  std::array<double, 4> g3;    // Table G.3 FS, FP, AS, AP
  double total;                // Table G.3 total column
};

// Table F.2 and Table G.3, transcribed.
const std::array<Case, 10> kCases = {{
    {"1", 0.0, 0.0, 0.0, {0.0, 0.0, 0.0, 0.0}, 0.0},
    {"2a", +0.5, 0.0, 0.0, {1.2, 1.2, 1.2, 1.2}, 4.8},
    {"2b", -0.5, 0.0, 0.0, {-1.2, -1.2, -1.2, -1.2}, -4.8},
    {"3", 0.0, +0.8, 0.0, {1.2, 1.2, -1.2, -1.2}, 0.0},
    {"4", 0.0, 0.0, -0.3, {1.2, -1.2, 1.2, -1.2}, 0.0},
    {"5", 0.0, -0.8, +0.3, {-1.2, 0.0, 0.0, 1.2}, 0.0},
    {"6a", +0.5, +0.8, +0.3, {1.2, 1.2, 0.0, 1.2}, 3.6},
    {"6b", -0.5, -0.8, -0.3, {0.0, -2.4, 0.0, -1.2}, -3.6},
    {"6c", +0.5, -0.8, -0.3, {1.2, 0.0, 1.2, 1.2}, 3.6},
    {"6d", -0.5, +0.8, +0.3, {-1.2, 0.0, -3.6, -1.2}, -6.0},
}};

ClassicResult run(const Case& c) {
  ClassicInput in;
  in.installed_kg = {10.8, 10.8, 22.8, 22.8};
  in.depth_error_m = c.depth;
  in.pitch_error_deg = c.pitch;
  in.roll_deg = c.roll;
  return classicAdjustment(in);
}

bool matchesG3(const ClassicResult& r, const Case& c) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (std::abs(r.change_kg[i] - c.g3[i]) > 1e-9) return false;
  }
  return true;
}

}  // namespace

TEST(ClassicTable, TableG3TotalsAreTheSumOfTheirRows) {
  // Guards the transcription itself.
  for (const Case& c : kCases) EXPECT_NEAR(c.g3[0] + c.g3[1] + c.g3[2] + c.g3[3], c.total, 1e-9) << c.name;
}

TEST(ClassicTable, ReproducesTableG3WhereThePrintedCodeAgrees) {
  for (const std::string n : {"1", "2a", "2b", "3", "4", "5", "6b"}) {
    for (const Case& c : kCases) {
      if (c.name != n) continue;
      const ClassicResult r = run(c);
      EXPECT_TRUE(matchesG3(r, c)) << "case " << n << ": got " << r.change_kg[0] << ", " << r.change_kg[1] << ", "
                                   << r.change_kg[2] << ", " << r.change_kg[3];
      EXPECT_FALSE(r.blocked);
    }
  }
}

TEST(ClassicTable, Cases6a6cAnd6dFollowFigureE1NotTableG3) {
  // Each of these G.3 rows has one small piece less (6a, 6c) or more (6d) at
  // the point Fig. E.1/E.2 and App. E.2 move by two; we keep the printed table.
  struct Want {
    std::size_t index;
    const char* weight, *pitch, *roll;
    std::array<double, 4> change;
  };
  for (const Want& w : {Want{6, "W < B", "negative", "negative", {1.2, 2.4, 0.0, 1.2}},     // add, add x2, -, add
                        Want{8, "W < B", "positive", "positive", {1.2, 0.0, 2.4, 1.2}},     // add, -, add x2, add
                        Want{9, "W > B", "negative", "negative", {-1.2, 0.0, -2.4, -1.2}}}) {  // rem, -, rem x2, rem
    const Case& c = kCases[w.index];
    const ClassicResult r = run(c);
    EXPECT_EQ(r.weight_case, w.weight) << c.name;
    EXPECT_EQ(r.pitch_sign, w.pitch) << c.name;
    EXPECT_EQ(r.roll_sign, w.roll) << c.name;
    int differ = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_NEAR(r.change_kg[i], w.change[i], 1e-9) << c.name << " point " << i;
      differ += std::abs(r.change_kg[i] - c.g3[i]) > 1e-9;
    }
    EXPECT_EQ(differ, 1) << c.name;
  }
}

TEST(ClassicTable, NeverMovesMoreThanTwoSmallPiecesPerPoint) {
  // The slow loop's defining property: whatever the size of the error.
  for (double depth : {-5.0, -0.05, 0.05, 5.0}) {
    for (double pitch : {-20.0, 0.0, 20.0}) {
      for (double roll : {-5.0, 0.0, 5.0}) {
        ClassicInput in;
        in.installed_kg = {10.8, 10.8, 22.8, 22.8};
        in.depth_error_m = depth;
        in.pitch_error_deg = pitch;
        in.roll_deg = roll;
        const ClassicResult r = classicAdjustment(in);
        for (double c : r.change_kg) EXPECT_LE(std::abs(c), 2.4 + 1e-9);
      }
    }
  }
}

TEST(ClassicTable, CannotRemoveWhatIsNotThere) {
  // Balanced, nose up (e_p < 0) with nothing aft: the table does nothing
  // (Fig. E.1, second half: "no weights in one or more points").
  ClassicInput in;
  in.installed_kg = {10.8, 10.8, 0.0, 0.0};
  in.depth_error_m = 0.05;
  in.pitch_error_deg = 2.0;
  const ClassicResult r = classicAdjustment(in);
  EXPECT_TRUE(r.blocked);
  for (double c : r.change_kg) EXPECT_EQ(c, 0.0);
  // Too heavy, nose up, port down, one piece at aft-port only: the full row
  // (FP, AS and 2 x AP) is impossible, the code's fallback removes that piece.
  in.installed_kg = {0.0, 0.0, 0.0, 1.2};
  in.depth_error_m = -0.5;
  in.pitch_error_deg = 2.0;  // e_p < 0
  in.roll_deg = -1.0;        // e_r > 0
  const ClassicResult h = classicAdjustment(in);
  EXPECT_FALSE(h.blocked);
  EXPECT_DOUBLE_EQ(h.change_kg[3], -1.2);
  EXPECT_DOUBLE_EQ(h.change_kg[0] + h.change_kg[1] + h.change_kg[2], 0.0);
}

TEST(ClassicTable, DepthBandEdgesAreTheSpec) {
  // Deviation 0..0.1 m is in band (thesis §5.1 item 7a); just outside is light or heavy.
  ClassicInput in;
  in.installed_kg = {10.8, 10.8, 22.8, 22.8};
  for (auto [dev, expect] : {std::pair{0.0, "W = B"}, {0.1, "W = B"}, {0.1001, "W < B"}, {-0.0001, "W > B"}}) {
    in.depth_error_m = dev;
    EXPECT_EQ(classicAdjustment(in).weight_case, expect) << dev;
  }
}

TEST(ClassicTable, BuoyancyTermOnlyWhenTheComputationContradictsTheDepth) {
  // e_b = W - B (eq. 5.19). Light by depth and light by computation: the
  // table alone. Light by depth but 30 kg heavy by computation:
  // m_dif = 30/4 - 4 x 1.2 = 2.7 kg more, split fore/aft by the other pair's
  // lever arm (App. E.2, too-heavy branch's parenthesisation).
  ClassicInput in;
  in.installed_kg = {0, 0, 0, 0};
  in.depth_error_m = 1.0;
  in.computed_imbalance_kg = 30.0;  // B - W: light
  ClassicResult r = classicAdjustment(in);
  for (double t : r.target_kg) EXPECT_DOUBLE_EQ(t, 1.2);
  in.computed_imbalance_kg = -30.0;  // heavy
  r = classicAdjustment(in);
  const double m_dif = 30.0 / 4 - 4.8, xf = 1.0325, xa = 0.49341;
  EXPECT_NEAR(r.target_kg[0], 1.2 + xa / (xf + xa) * m_dif / 2, 1e-12);
  EXPECT_NEAR(r.target_kg[2], 1.2 + xf / (xf + xa) * m_dif / 2, 1e-12);
  EXPECT_NEAR(r.target_kg[0] + r.target_kg[1] + r.target_kg[2] + r.target_kg[3], 30.0 / 4, 1e-12);
}

TEST(ClassicTable, ReproducesTheWholeSystemRunOfTable72) {
  // Fig. 7.9 row 3 (post mission): 9.6:9.6:24:24 kg installed, 1565.2 kg,
  // depth +8.7594 m, pitch -0.59959 deg, roll +0.73636 deg, 6.545581 degC,
  // 34.4975 PSU. Table 7.2 "Pre, mapped": 0.0, 1.2, 1.2, 2.4 (total 4.8),
  // and row 4 of Fig. 7.9 is 9.6:10.8:25.2:26.4 kg, 1570 kg.
  ClassicInput in;
  in.installed_kg = {9.6, 9.6, 24.0, 24.0};
  in.depth_error_m = 8.7594;
  in.pitch_error_deg = -0.59959;
  in.roll_deg = 0.73636;
  in.computed_imbalance_kg = 1.3;  // B - W at that water is about +1.3 kg (light)
  const ClassicResult r = classicAdjustment(in);
  const std::array<double, 4> change{0.0, 1.2, 1.2, 2.4}, after{9.6, 10.8, 25.2, 26.4};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(r.change_kg[i], change[i], 1e-9) << i;
    EXPECT_NEAR(r.mapped_kg[i], after[i], 1e-9) << i;
  }
  EXPECT_NEAR(1565.2 + r.change_kg[0] + r.change_kg[1] + r.change_kg[2] + r.change_kg[3], 1570.0, 1e-9);
}
