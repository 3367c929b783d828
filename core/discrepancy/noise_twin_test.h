#pragma once
// Step 4b of the model check: an accepted term must stand out from what the
// same check fits on the log's noise twin (CheckModel::noiseTwin): the logged
// commands flown by the fitted vehicle without the term, the autopilot
// steering on readings with the log's own sensor noise. A closed loop turns
// sensor noise into real motion, and the equation error's regressors carry
// that noise: on pitch-stable HUGIN truths without any missing physics the
// check named a quadratic pitch damping or a pitch-sensor bias that the
// noise-free flight of the same truths did not show. Where the twin, which
// has no such term, gives the term the same value, the log's value is what
// the closed loop makes of noise, not physics. Internal to the model check.
#include "discrepancy/model_check.h"
#include "discrepancy/term_acceptance.h"

namespace auv::discrepancy::detail {

// Removes from `acc` (and marks in R.candidates) each accepted term whose
// value the twin's check matches: |value - twin value| below
// o.min_twin_z x hypot(sigma, twin sigma), the linearised full-data fits
// with the ballast state (CandidateReport::value, sigma) on both logs.
void testAgainstNoiseTwin(const CheckModel& m, const Params& base,
                          const ModelCheckOptions& o, TermAcceptance& acc, ModelCheckResult& R);

}  // namespace auv::discrepancy::detail
