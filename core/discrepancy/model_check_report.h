#pragma once
// The model check's JSON contract (issue 5): added to the post-mission
// analysis report as
//   "missing_physics": [ {"id", "value", "unit", "sigma", "rms_before",
//                         "rms_after", "channel", "where", ...}, ... ]  best first
//   "net_buoyancy_kg", "net_buoyancy_sigma_kg", "cg_offset_mm" {x, y}: re-estimated
//                         jointly with the accepted terms
//   "model_check": { candidates, identifiability, rms per channel (fitted and
//                    held-out, before and after), localisation, notes }
// rms_before/rms_after are the held-out simulation RMS on `channel`, in the
// channel's unit (cm/s for vertical velocity, deg for angles, m for depth).
#include <string>

#include <nlohmann/json.hpp>

#include "discrepancy/model_check.h"

namespace auv::discrepancy {

nlohmann::json toJson(const ModelCheckResult& r);

// Adds the contract fields above to an analysis report (analysis::toJson),
// keeping the analysis's own estimates under model_check.analysis_estimate.
void mergeIntoAnalysisJson(nlohmann::json& analysis, const ModelCheckResult& r);

std::string toText(const ModelCheckResult& r);

}  // namespace auv::discrepancy
