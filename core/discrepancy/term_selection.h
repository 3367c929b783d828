#pragma once
// Step 3 of the model check: which candidate terms this log can identify
// (collinearity with the ballast state and with each other), forward
// stepwise selection and bootstrap inclusion over the identifiable ones, the
// STLSQ comparison, and a report line per candidate. Internal to the model check.
#include <cstddef>
#include <vector>

#include "discrepancy/model_check.h"
#include "discrepancy/sparse_selection.h"
#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy::detail {

struct TermSelection {
  Collinearity coll;           // candidate regressors after the ballast state (with its priors)
  SelectionResult sel;         // over the identifiable candidates
  std::vector<double> incl;    // bootstrap inclusion probability per candidate (0 if not identifiable)
  Eigen::MatrixXd together;    // fraction of replicates selecting both candidates k and l
};

// `cand`: library indices of the candidates, columns s.nN + k of `lp`.
// Fills R.stlsq_selected, R.candidates (status "not selected" until the
// held-out check says otherwise) and R.identifiability.
TermSelection selectTerms(const FitSetup& s, const LinearProblem& lp, const std::vector<std::size_t>& cand,
                          const ModelCheckOptions& o, ModelCheckResult& R);

}  // namespace auv::discrepancy::detail
