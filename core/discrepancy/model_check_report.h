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
// An AUV's ballast state follows planEstimate (plan_estimate.h): the
// check's fit replaces the analysis's only where the analysis did not
// identify it, or when the terms were accepted (`terms_accepted`, e.g.
// --accept), then with the widened sigma; otherwise the analysis's stands
// and the check's is kept as model_check.check_estimate. A glider's is the
// check's (its flight-model fit is the glider answer).
void mergeIntoAnalysisJson(nlohmann::json& analysis, const ModelCheckResult& r, bool terms_accepted = false);

std::string toText(const ModelCheckResult& r);

}  // namespace auv::discrepancy
