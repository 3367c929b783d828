#pragma once
// The steady segments an AUV analysis used, as JSON in its report
// (details.auv_estimate.steady_segments), so a later mission of the same
// configuration can calibrate jointly with them from the history (issue 11
// item 3): per segment the means and standard errors the calibration reads
// and the in-situ buoyancy rho V g.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/auv_trim_estimation.h"

namespace auv::analysis {

nlohmann::json steadySegmentsJson(const std::vector<SteadySegmentMeans>& segments);

// InputError naming `where` and the field when an entry is malformed.
std::vector<SteadySegmentMeans> steadySegmentsFromJson(const nlohmann::json& j, const std::string& where);

}  // namespace auv::analysis
