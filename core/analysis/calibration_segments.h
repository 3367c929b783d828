#pragma once
// The steady segments of the calibration (auv_calibration.h) as a pitch
// sensor with a known bias would have read them.
#include <vector>

#include "analysis/auv_calibration.h"
#include "analysis/auv_trim_estimation.h"

namespace auv::analysis {

// Every segment's pitch lowered by bias_rad (reading minus true), and an
// averaged leg's cycle products (BalanceRegressors) moved by what that shift
// moves the products of its means: the balance is then the true attitude's.
std::vector<CalibrationSegment> withPitchLowered(const std::vector<CalibrationSegment>& segs, double bias_rad);

// A steady segment's pitch and roll means raised by pitch_deg and roll_deg,
// its cycle products moved the same way: an earlier mission's segment read
// with a smaller accepted bias taken out than the one it had.
SteadySegmentMeans withAttitudeRaised(SteadySegmentMeans s, double pitch_deg, double roll_deg);

}  // namespace auv::analysis
