#pragma once
// Library terms the analysis calibrated and the check holds (its hull law
// and mass drift, AuvCheckOptions::held_terms) reported as missing physics when they are
// 2 sigma from the profile's: the vehicle's value and sigma are the
// analysis's, and the fit's improvement is measured here, the log simulated
// with the term and with the profile's value (the ballast state and the
// accepted terms refitted without it).
#include <cstdint>
#include <vector>

#include "discrepancy/model_check.h"
#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy::detail {

void reportHeldTermFindings(const FitSetup& s, const std::vector<std::uint32_t>& fitRows,
                            const std::vector<std::size_t>& accepted, const Fit& fin, const std::vector<std::uint32_t>& all,
                            std::vector<MissingPhysics>& found, ModelCheckResult& R);

}  // namespace auv::discrepancy::detail
