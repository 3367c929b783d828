#pragma once
// Test helper (gtest): the model check as the CLI and the wizard run it on
// the identification harness's first log of a drawn truth.
#include <cstdint>
#include <functional>

#include "discrepancy/model_check.h"
#include "identification_harness.h"

namespace auv::identification {

// The model check as the CLI and the wizard run it (with the log's
// analysis) on the first log of drawn truth `seed`, flown with `concealed`;
// `expect` sees its result, the analysis and the harness.
using FirstLogCheck = std::function<void(const discrepancy::ModelCheckResult&, const analysis::AnalysisReport&,
                                         double net_truth, const Harness&)>;
void checkFirstLogWithItsAnalysis(std::uint64_t seed, const FirstLogCheck& expect,
                                  const discrepancy::SyntheticAuvTruth& concealed = {},
                                  double pitch_alignment_sigma_deg = 1.0);

}  // namespace auv::identification
