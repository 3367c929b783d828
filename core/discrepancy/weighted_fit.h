#pragma once
// The model check's nonlinear fit: the ballast state (always) plus a set of
// library terms, by Levenberg-Marquardt on the equation error, each channel
// weighted by its noise level and effective sample size. Internal to the
// model check (model_check.cpp).
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "discrepancy/check_model.h"

namespace auv::discrepancy::detail {

// What every fit of one check shares. The weights (sigma, eff) are refined
// as the check learns the noise, so they live here rather than in the model.
struct FitSetup {
  const CheckModel& m;
  std::vector<Channel> eq;
  std::size_t C = 0;
  int nN = 0;
  Eigen::VectorXd nScale, nLo, nHi;
  std::vector<double> sigma;  // per equation channel
  std::vector<NuisancePrior> priors;
  std::vector<double> eff;    // per channel: effective / actual sample size (AR(1) of the residuals)
  // Fitted terms held at a value (library index -> value): the fit without a
  // term the analysis calibrated (held_term_findings.h).
  std::vector<std::pair<std::size_t, double>> pinned_terms;
  double weight(std::size_t c) const { return std::sqrt(eff[c]) / sigma[c]; }
};

struct Fit {
  Params params;
  Eigen::VectorXd x, sigma;  // nuisance first, then the fitted terms in order
  double cost = 0.0;
};

// `terms`: library indices fitted beside the ballast state, from `start`.
Fit fit(const FitSetup& s, const std::vector<std::uint32_t>& rows, const std::vector<std::size_t>& terms, const Params& start);

// Unweighted equation error at `rows`, row-major (rows.size() x s.C), NaN where not available.
std::vector<double> residualsAt(const FitSetup& s, const Params& p, const std::vector<std::uint32_t>& rows);

}  // namespace auv::discrepancy::detail
