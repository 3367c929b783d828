#pragma once
// Roll at rest and at cruise from a survey's steady segments: the static CG y
// (propeller torque fitted where the log flew several rpm) and the
// cruise-equivalent CG y the plan levels the vehicle on.
#include <span>

#include "analysis/auv_trim_estimation.h"

namespace auv::analysis {

// Fills the roll, CG y and propeller-torque parts of `out`.
void estimateRoll(std::span<const SteadySegmentMeans> segments, const AuvTrimContext& ctx, AuvTrimEstimate& out);

}  // namespace auv::analysis
