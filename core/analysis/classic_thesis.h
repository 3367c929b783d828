#pragma once
// The thesis's post-mission checks (Lillemoen 2014, App. D.1-D.4), kept as a
// documented 'classic' mode so results can be compared with the original
// tool. They are reproduced as written, quirks included (see
// docs/decisions/analysis-classic-mode.md):
//  - a fixed 40-60 % window of the record instead of detected segments;
//  - exact equality tests (commanded depth unchanged, depth unchanged over
//    three samples, rpm == 160), which real noisy data rarely satisfy;
//  - D.1 leaves zeros (not NaN) in the samples it skips after a command step,
//    and applies the window indices to the array after NaNs were removed.
// Inputs are index-aligned arrays like the thesis's MATLAB vectors; NaN
// is MATLAB's NaN. A result is NaN when no sample passes (MATLAB's 0/0).
#include <cstddef>
#include <span>

#include "missionlog/mission_log.h"

namespace auv::analysis::classic {

struct ClassicValue {
  double value = 0.0;       // NaN when no sample passed
  std::size_t samples = 0;  // samples averaged (including D.1's zeros)
  bool index_clamped = false;  // D.1: window end beyond the shortened array (MATLAB would stop with an error)
};

// D.1: mean of commanded - measured depth; positive = did not reach down = too light.
ClassicValue depthComparison(std::span<const double> commanded_depth, std::span<const double> measured_depth);
// D.2: mean of measured - commanded pitch in the window; negative = nose down.
ClassicValue pitchComparison(std::span<const double> measured_pitch, std::span<const double> commanded_pitch);
// D.3: mean pitch where depth(i) == depth(i-1) == depth(i-2), in the window.
ClassicValue pitchAtStableDepth(std::span<const double> measured_pitch, std::span<const double> measured_depth);
// D.4: mean roll where rpm == rpm_exact and |speed - speed_center| < speed_half_band (whole record).
ClassicValue rollAtCruise(std::span<const double> roll, std::span<const double> rpm, std::span<const double> speed,
                          double rpm_exact = 160.0, double speed_center = 2.0, double speed_half_band = 0.005);

struct ClassicReport {
  ClassicValue depth_error_m, pitch_error_deg, pitch_at_stable_depth_deg, roll_error_deg;
  bool has_depth = false, has_pitch = false, has_pitch_depth = false, has_roll = false;
};

// Runs D.1-D.4 on a log. The thesis's files were index-aligned; here each
// check runs on the valid samples of its measured channel with commands held
// and other measured channels linearly interpolated onto those times.
ClassicReport classicAnalysis(const MissionLog& log, double rpm_exact = 160.0, double speed_center = 2.0);

}  // namespace auv::analysis::classic
