#include "discrepancy/weighted_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <tuple>

#include "discrepancy/levenberg_marquardt.h"

namespace auv::discrepancy::detail {

namespace {

Params toParams(const FitSetup& s, const Eigen::VectorXd& x, const std::vector<std::size_t>& terms) {
  Params p;
  p.nuisance = x.head(s.nN);
  for (std::size_t k = 0; k < terms.size(); ++k) p.terms[terms[k]] = x[s.nN + static_cast<Eigen::Index>(k)];
  return p;
}

Eigen::VectorXd fromParams(const FitSetup& s, const Params& p, const std::vector<std::size_t>& terms) {
  Eigen::VectorXd x(s.nN + static_cast<Eigen::Index>(terms.size()));
  x.head(s.nN) = p.nuisance;
  for (std::size_t k = 0; k < terms.size(); ++k) x[s.nN + static_cast<Eigen::Index>(k)] = p.terms[terms[k]];
  return x;
}

LmProblem makeProblem(const FitSetup& s, const std::vector<std::uint32_t>& rows, const std::vector<std::size_t>& terms) {
  LmProblem p;
  const Eigen::Index K = s.nN + static_cast<Eigen::Index>(terms.size());
  p.scale.resize(K);
  p.lower.resize(K);
  p.upper.resize(K);
  p.scale.head(s.nN) = s.nScale;
  p.lower.head(s.nN) = s.nLo;
  p.upper.head(s.nN) = s.nHi;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const PhysicsTerm& t = termLibrary()[terms[k]];
    const auto j = s.nN + static_cast<Eigen::Index>(k);
    p.scale[j] = t.typical;
    std::tie(p.lower[j], p.upper[j]) = s.m.termRange(terms[k]);
    for (const auto& [term, value] : s.pinned_terms)
      if (term == terms[k]) p.lower[j] = p.upper[j] = value;
  }
  p.residuals = [&s, &rows, terms](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    std::vector<double> out(rows.size() * s.C);
    s.m.equationError(toParams(s, x, terms), rows, out.data());
    r.resize(static_cast<Eigen::Index>(out.size() + s.priors.size()));
    for (std::size_t i = 0; i < out.size(); ++i)
      r[static_cast<Eigen::Index>(i)] = std::isfinite(out[i]) ? out[i] * s.weight(i % s.C) : 0.0;
    for (std::size_t k = 0; k < s.priors.size(); ++k) {
      const NuisancePrior& q = s.priors[k];
      r[static_cast<Eigen::Index>(out.size() + k)] = (x[q.index] - q.mean) / q.sigma;
    }
  };
  return p;
}

}  // namespace

Fit fit(const FitSetup& s, const std::vector<std::uint32_t>& rows, const std::vector<std::size_t>& terms, const Params& start) {
  const LmProblem prob = makeProblem(s, rows, terms);
  LmOptions lo;
  lo.max_iterations = 30;
  const LmResult r = levenbergMarquardt(prob, fromParams(s, start, terms), lo);
  Fit f;
  f.x = r.x;
  f.params = toParams(s, r.x, terms);
  f.cost = r.cost;
  // Covariance from J'J of the effectively weighted residuals (a chi-square on
  // the effective sample size), scaled up when the fit is worse than the
  // noise estimate says (quasi-likelihood dispersion).
  double neff = 0.0;
  for (Eigen::Index i = 0; i + static_cast<Eigen::Index>(s.priors.size()) < r.r.size(); ++i)
    if (r.r[i] != 0.0) neff += s.eff[static_cast<std::size_t>(i) % s.C];
  const double s2 = std::max(1.0, r.cost / std::max(1.0, neff - static_cast<double>(r.x.size())));
  Eigen::MatrixXd A = r.JtJ;
  for (Eigen::Index j = 0; j < A.rows(); ++j) A(j, j) = std::max(A(j, j), 1e-300);
  const Eigen::MatrixXd cov = A.ldlt().solve(Eigen::MatrixXd::Identity(A.rows(), A.cols())) * s2;
  f.sigma = cov.diagonal().cwiseMax(0.0).cwiseSqrt();
  return f;
}

std::vector<double> residualsAt(const FitSetup& s, const Params& p, const std::vector<std::uint32_t>& rows) {
  std::vector<double> out(rows.size() * s.C);
  s.m.equationError(p, rows, out.data());
  return out;
}

}  // namespace auv::discrepancy::detail
