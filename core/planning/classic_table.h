#pragma once
// The thesis's pre-mission "slow control loop" (Lillemoen 2014, §5.4.2,
// App. E.1 tables and E.2 MATLAB code), kept as the 'classic' policy so a
// user can compare: from the SIGNS of the depth, pitch and roll deviations it
// adds or removes one smallest piece (1.2 kg) at two to four points per
// mission, never more. Readings (docs/decisions/planning-classic-table.md):
//  - inputs are the post-mission deviations with their App. D signs (depth
//    commanded - measured, pitch measured - commanded, roll); the code works
//    on errors e = reference - deviation (eq. 5.18-5.21), i.e. their negation;
//  - a deviation exactly at a threshold counts as neutral (the code's strict
//    comparisons leave that case undefined);
//  - the m_dif term uses e_b = W - B as eq. 5.19 defines it (so it acts only
//    when the computed balance contradicts the depth deviation; this is what
//    reproduces the thesis's whole-system run, Table 7.2), with the fore/aft
//    split of the too-heavy branch (the light branch's |x7|/|x5| + |x7| is a
//    precedence slip);
//  - new totals per point are mapped onto the kit largest piece first
//    (eq. 5.22-5.26), in exact 0.1 g quanta.
#include <array>
#include <string>
#include <vector>

namespace auv {

struct ClassicThresholds {
  double depth_lo_m = 0.0, depth_hi_m = 0.1;  // deviation band of the spec (thesis §5.1 item 7a)
  double pitch_deg = 0.5, roll_deg = 0.1;
  double weight_kg = 1.2;                     // tolerance on the computed B - W
};

struct ClassicInput {
  std::array<double, 4> installed_kg{};  // FS, FP, AS, AP (thesis order)
  double depth_error_m = 0.0;            // commanded - measured, + = too light
  double pitch_error_deg = 0.0;          // measured - commanded, + = nose up
  double roll_deg = 0.0;                 // + = starboard down
  double computed_imbalance_kg = 0.0;    // B - W from the weighing model (eq. 5.2), + = light
  double x_fore_m = 1.0325, x_aft_m = -0.49341;  // x_aw(1), x_aw(3)
  double small_piece_kg = 1.2;           // w_small
  std::vector<double> piece_sizes_kg = {1.2, 2.4, 4.8};  // ascending, for the mapping
  ClassicThresholds thresholds;
};

struct ClassicResult {
  std::array<double, 4> target_kg{};  // the table's new totals (calculatedAdjustment)
  std::array<double, 4> mapped_kg{};  // after mapping onto the pieces
  std::array<double, 4> change_kg{};  // mapped - installed
  std::string weight_case;            // "W = B", "W < B" or "W > B"
  std::string pitch_sign, roll_sign;  // "negative", "neutral", "positive" (of the errors e)
  bool blocked = false;               // no piece to remove where the table needs one: nothing done
};

ClassicResult classicAdjustment(const ClassicInput& in);

// Largest piece first with floors, eq. 5.22-5.26, in exact 0.1 g quanta.
double mapOntoPieces(double mass_kg, const std::vector<double>& sizes_ascending);

}  // namespace auv
