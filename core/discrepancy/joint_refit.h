#pragma once
// Step 5 of the model check: the ballast state re-estimated jointly with the
// accepted terms, and what is reported from it (net buoyancy and CG with
// their sigmas, each accepted term's value and sigma). Internal to the model check.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "discrepancy/model_check.h"
#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy::detail {

// Starts from `base` with the provisional values in R.accepted. Sets
// R.final_params, R.accepted, R.nuisance(_sigma), the net buoyancy and CG
// with sigmas, R.calibration, and value/sigma of every entry of `found`.
Fit jointRefit(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const std::vector<std::size_t>& accepted,
               const Params& base, std::vector<MissingPhysics>& found, ModelCheckResult& R);

// The model's calibration constants at `fin` into R.calibration, with a
// finding in words for each the log puts far from the profile's value.
void reportCalibration(const CheckModel& m, const Fit& fin, ModelCheckResult& R);

}  // namespace auv::discrepancy::detail
