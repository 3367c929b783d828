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
  kHistoryJoint,  // the analysis calibrated jointly with the configuration's earlier mission (history)
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
//
// An adopted value keeps the check's centre but not its bare sigma: the
// check's sigma assumes its model structure is right, the analysis's
// calibrated one has measured coverage (bench/identification_bench). So
// sigma = hypot(max(sigma_check, sigma_analysis), |check - analysis|): the
// analysis's sigma is the floor, and a disagreement the accepted terms do
// not explain is model error of one of the two, which the plan's margin
// must cover. Measured: on HUGIN logs with no concealed effect the check
// named a false depth offset and its fit was 9-10 sigma off the truth
// (net 6.46 +- 0.11 kg against 5.29; CG x 44 sigma), which a plan with its
// bare sigma would have trusted (docs/decisions/model-check-calibration.md).
// Where `pitch_sensor_bias` is accepted and the check analysed the log again
// without it (ModelCheckResult::analysis_without_pitch_bias), that analysis
// is the analysis side of the rule: read as true, the biased pitch put the
// analysis 2.7 kg off at 3.8 sigma (median, identification_bench
// --pitch-bias 1), and the check's bare fit covered 26 of 50.
PlanEstimate planEstimate(const analysis::AnalysisReport& analysis, const ModelCheckResult* check,
                          const std::vector<std::string>& accepted_terms);

// The rule above for one quantity: the check's value, its sigma widened.
double adoptedSigma(double analysis_value, double analysis_sigma, double check_value, double check_sigma);

}  // namespace auv::discrepancy
