#include "discrepancy/linearised_problem.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "discrepancy/residual_statistics.h"

namespace auv::discrepancy::detail {

Linearisation linearise(const FitSetup& s, const Params& at, const std::vector<std::size_t>& cand,
                        const std::vector<std::uint32_t>& all) {
  const auto& lib = termLibrary();
  const Eigen::Index P = s.nN + static_cast<Eigen::Index>(cand.size());
  const auto NR = static_cast<Eigen::Index>(all.size() * s.C);
  Linearisation lin;
  lin.e.resize(NR);
  lin.J.resize(NR, P);
  lin.raw = residualsAt(s, at, all);
  for (Eigen::Index i = 0; i < NR; ++i) {
    const double v = lin.raw[static_cast<std::size_t>(i)];
    lin.e[i] = std::isfinite(v) ? v * s.weight(static_cast<std::size_t>(i) % s.C) : 0.0;
  }
  auto column = [&](const Params& plus, const Params& minus, double h, Eigen::Index col) {
    const std::vector<double> a = residualsAt(s, plus, all), b = residualsAt(s, minus, all);
    for (Eigen::Index i = 0; i < NR; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const double d = -(a[k] - b[k]) / (2.0 * h);  // d(model)/d(parameter in its scale)
      lin.J(i, col) = std::isfinite(d) ? d * s.weight(k % s.C) : 0.0;
    }
  };
  for (int j = 0; j < s.nN; ++j) {
    Params a = at, b = at;
    a.nuisance[j] += 1e-2 * s.nScale[j];
    b.nuisance[j] -= 1e-2 * s.nScale[j];
    column(a, b, 1e-2, j);
  }
  for (std::size_t k = 0; k < cand.size(); ++k) {
    Params a = at, b = at;
    a.terms[cand[k]] = lib[cand[k]].typical;
    b.terms[cand[k]] = -lib[cand[k]].typical;
    column(a, b, 1.0, s.nN + static_cast<Eigen::Index>(k));
  }
  return lin;
}

void weightsFromLargestModel(FitSetup& s, const SampleTable& S, const Linearisation& lin) {
  const Eigen::MatrixXd& J = lin.J;
  const Eigen::Index NR = J.rows(), P = J.cols();
  Eigen::MatrixXd A = J.transpose() * J;
  const double ridge = 1e-9 * std::max(1e-300, A.trace() / static_cast<double>(P));
  A.diagonal().array() += ridge;
  const Eigen::VectorXd beta = A.ldlt().solve(J.transpose() * lin.e);
  const Eigen::VectorXd ef = lin.e - J * beta;
  std::vector<double> full(static_cast<std::size_t>(NR));
  for (Eigen::Index i = 0; i < NR; ++i) {
    const auto k = static_cast<std::size_t>(i);
    full[k] = std::isfinite(lin.raw[k]) ? ef[i] / s.weight(k % s.C) : kNaN;
  }
  s.sigma = robustSigmas(s, full);
  s.eff = effectiveShares(s, S, full);
}

LinearProblem selectionProblem(const FitSetup& s, const SampleTable& S, const Linearisation& lin, int units,
                               const Params& base, double& neff_ratio) {
  double nEff = 0.0, nAll = 0.0;
  for (std::size_t i = 0; i < lin.raw.size(); ++i)
    if (std::isfinite(lin.raw[i])) {
      nEff += s.eff[i % s.C];
      nAll += 1.0;
    }
  neff_ratio = nAll > 0 ? nEff / nAll : 1.0;
  const auto NR = static_cast<std::size_t>(lin.J.rows());
  std::vector<int> unitOfResidual(NR);
  for (std::size_t i = 0; i < NR; ++i) unitOfResidual[i] = S.unit[i / s.C];
  LinearProblem lp = buildLinearProblem(lin.J, lin.e, unitOfResidual, units, s.nN, nEff);
  for (const NuisancePrior& q : s.priors) {
    const double a = s.nScale[q.index] / q.sigma;
    lp.prior_G(q.index, q.index) += a * a;
    lp.prior_h[q.index] += a * (q.mean - base.nuisance[q.index]) / q.sigma;
  }
  return lp;
}

}  // namespace auv::discrepancy::detail
