#pragma once
// Sparse selection over the term library on the problem linearised around the
// base fit (ballast state only): e ~ J d, J = d(model)/d(parameter). The
// normal equations are summed per cross-validation unit (dive/yo or leg), so
// every subset fit, every fold and every bootstrap replicate is a small
// P x P solve, independent of the log length.
//
// Selection is forward stepwise with a Bayesian information criterion on the
// effective sample size (residuals of a flight log are strongly
// autocorrelated; counting every sample as independent would accept noise),
// a t-test of the new coefficient, and K-fold cross-validation across units;
// a bootstrap over units re-runs the selection to give each term an
// inclusion probability (ensembling). See docs/decisions/model-check-selection.md.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace auv::discrepancy {

struct LinearProblem {
  int n_nuisance = 0;                // the first columns, always in the model
  std::vector<Eigen::MatrixXd> G;    // per unit: J'J
  std::vector<Eigen::VectorXd> h;    // per unit: J'e
  std::vector<double> s;             // per unit: e'e
  std::vector<double> n;             // per unit: number of residuals
  Eigen::MatrixXd prior_G;           // nuisance priors (added to every training fit)
  Eigen::VectorXd prior_h;
  // Residual rows come pre-weighted by sqrt(n_eff/n) of their channel, so
  // that their sum of squares is a chi-square on the effective sample size
  // (autocorrelated residuals carry less information than their count).
  double n_eff = 1.0;                // effective number of residuals, all units
  double dispersion = 1.0;           // max(1, chi2/n_eff) of the base fit: quasi-likelihood scale
  int P() const { return static_cast<int>(prior_h.size()); }
  int units() const { return static_cast<int>(G.size()); }
};

// J: residuals x P (model derivatives), e: base residuals (weighted, 0 where
// missing), unit of each residual in [0, n_units); rows with unit < 0 are skipped.
LinearProblem buildLinearProblem(const Eigen::MatrixXd& J, const Eigen::VectorXd& e, std::span<const int> unit,
                                 int n_units, int n_nuisance, double n_eff);

struct SubsetFit {
  bool ok = false;
  Eigen::VectorXd beta;  // over `cols`
  double rss = 0.0;
  double n = 0.0;
  Eigen::VectorXd sigma;  // standard errors (times the dispersion)
};

// Least squares over the columns `cols` (nuisance columns must be included
// by the caller) with unit weights (1 = use, 0 = leave out, k = bootstrap count).
SubsetFit fitSubset(const LinearProblem& lp, const std::vector<int>& cols, const std::vector<double>& unit_weight);

// Sum of held-out squared residuals over K folds (unit u in fold u mod K).
double crossValidationError(const LinearProblem& lp, const std::vector<int>& cols, int folds);

struct SelectionOptions {
  double bic_threshold = 6.0;   // required drop of BIC(n_eff): "strong" evidence
  double min_t = 3.0;
  double min_cv_gain = 2.0;     // drop of the cross-validation chi-square (over the dispersion)
  int folds = 5;
  int max_terms = 4;
};

struct StepRecord {
  int column = -1;
  double delta_bic = 0.0;
  double cv_before = 0.0, cv_after = 0.0;
  double t_value = 0.0;
};

struct SelectionResult {
  std::vector<int> selected;  // term columns, in the order they were added
  std::vector<StepRecord> steps;
};

// `candidates`: term columns (>= n_nuisance). With use_cv false only BIC and
// t decide (bootstrap replicates).
SelectionResult forwardStepwise(const LinearProblem& lp, const std::vector<int>& candidates,
                                const std::vector<double>& unit_weight, const SelectionOptions& options, bool use_cv);

// Bootstrap over units: fraction of replicates in which each candidate is
// selected (same order as `candidates`), and in which each pair is selected
// together: two terms that each explain the same residual are picked in
// different replicates and hardly ever together (rivals, term_acceptance.h).
struct Inclusion {
  std::vector<double> p;
  Eigen::MatrixXd together;  // [i][j]: fraction of replicates with both i and j; diagonal = p
};
Inclusion inclusionStatistics(const LinearProblem& lp, const std::vector<int>& candidates, int replicates,
                              std::uint64_t seed, const SelectionOptions& options);
std::vector<double> inclusionProbabilities(const LinearProblem& lp, const std::vector<int>& candidates, int replicates,
                                           std::uint64_t seed, const SelectionOptions& options);

// Sequentially thresholded least squares (SINDy's STLSQ) on the scaled
// columns, for comparison with the stepwise result: fit all candidates,
// drop those with |beta| < threshold (in units of the column's typical
// value), refit, until stable.
std::vector<int> stlsq(const LinearProblem& lp, const std::vector<int>& candidates, double threshold);

// Identifiability on all data: correlation of the candidate columns after
// the nuisance columns are projected out, and the share of each candidate
// column that the nuisance explains.
struct Collinearity {
  Eigen::MatrixXd correlation;      // over candidates
  std::vector<double> nuisance_r2;  // per candidate
};
// `nuisance`: the nuisance columns to project out (default: all).
Collinearity collinearity(const LinearProblem& lp, const std::vector<int>& candidates,
                          const std::vector<int>& nuisance = {}, bool all_nuisance = true);

}  // namespace auv::discrepancy
