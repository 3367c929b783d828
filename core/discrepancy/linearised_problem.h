#pragma once
// The model check's problem linearised around the base fit (ballast state
// only): weighted residuals and their derivatives for the ballast state and
// every candidate term, from which the channel weights are re-estimated and
// the sparse selection's LinearProblem is built. Internal to the model check.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "discrepancy/sparse_selection.h"
#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy::detail {

struct Linearisation {
  std::vector<double> raw;  // unweighted equation error at every row, row-major
  Eigen::VectorXd e;        // weighted, 0 where not available
  Eigen::MatrixXd J;        // weighted d(model)/d(parameter in its scale): ballast state, then `cand`
};

// Central differences around `at`: 1e-2 of the scale for the ballast state,
// +-typical for each candidate term. `all`: every sample row.
Linearisation linearise(const FitSetup& s, const Params& at, const std::vector<std::size_t>& cand,
                        const std::vector<std::uint32_t>& all);

// Noise level and effective sample size per channel (s.sigma, s.eff) from the
// residuals of the largest model (every candidate in): the base residuals
// still hold the missing effect, whose own autocorrelation would understate n_eff.
void weightsFromLargestModel(FitSetup& s, const SampleTable& S, const Linearisation& lin);

// The selection problem, summed per unit, with the ballast-state priors;
// neff_ratio: effective / actual number of residuals.
LinearProblem selectionProblem(const FitSetup& s, const SampleTable& S, const Linearisation& lin, int units,
                               const Params& base, double& neff_ratio);

}  // namespace auv::discrepancy::detail
