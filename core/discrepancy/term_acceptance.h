#pragma once
// Step 4 of the model check: each selected term, in selection order, must
// have been picked in enough bootstrap replicates and must lower the held-out
// simulation cost (held_out_scoring.h) on top of the terms already accepted.
// Internal to the model check.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "discrepancy/held_out_scoring.h"
#include "discrepancy/model_check.h"
#include "discrepancy/term_selection.h"

namespace auv::discrepancy::detail {

struct TermAcceptance {
  std::vector<std::size_t> accepted;   // library indices, in the order accepted
  std::vector<MissingPhysics> found;   // one per accepted term, value/sigma/where not yet set
};

// Sets the status of each selected candidate in R.candidates and leaves the
// provisional fitted values of the accepted terms in R.accepted.
TermAcceptance acceptTerms(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const HeldOutScorer& scorer,
                           const TermSelection& ts, const std::vector<std::size_t>& cand, const Params& base,
                           const ModelCheckOptions& o, ModelCheckResult& R);

}  // namespace auv::discrepancy::detail
