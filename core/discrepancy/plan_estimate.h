#pragma once
// One estimate (issue 14 item 5): the ballast state the plan uses after a
// post-mission analysis and its model check, so the analysis page, the
// model-check page and the plan show the same numbers and say which it is.
#include <string>
#include <vector>

#include "analysis/analysis_report.h"
#include "discrepancy/model_check.h"

namespace auv::discrepancy {

enum class EstimateSource {
  kAnalysis,    // calibrated from this log by the analysis
  kModelCheck,  // the model check's joint fit with the terms the technician accepted
  kModelCheckReplay,  // the model check's fit of the whole log, where the analysis's steady flight could not tell
};

struct PlanEstimate {
  analysis::AnalysisReport report;  // the analysis with the adopted ballast state
  EstimateSource source = EstimateSource::kAnalysis;
};

// With at least one accepted term of `check` (an AUV's model check of the
// same log), net buoyancy and CG x are the model check's joint fit with its
// terms: those terms change what ballast state explains the log. CG y stays
// the analysis's, which uses the configuration's measured BG or says it is
// not known (the model check assumes the profile's BG). A model-check value
// without a positive finite sigma is not adopted. Otherwise: the analysis.
// The check's joint fit holds every term it accepted; unticking some (not
// all) keeps that fit, and the source says the accepted terms are in it.
// Without accepted terms, where the analysis did not identify the net
// buoyancy (e.g. Delphin2's tunnel thrusters ran in every steady segment)
// and the check's replay did: the check's fit (kModelCheckReplay).
PlanEstimate planEstimate(const analysis::AnalysisReport& analysis, const ModelCheckResult* check,
                          const std::vector<std::string>& accepted_terms);

}  // namespace auv::discrepancy
