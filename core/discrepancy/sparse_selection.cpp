#include "discrepancy/sparse_selection.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace auv::discrepancy {

LinearProblem buildLinearProblem(const Eigen::MatrixXd& J, const Eigen::VectorXd& e, std::span<const int> unit,
                                 int n_units, int n_nuisance, double n_eff) {
  LinearProblem lp;
  const auto P = J.cols();
  lp.n_nuisance = n_nuisance;
  lp.G.assign(static_cast<std::size_t>(n_units), Eigen::MatrixXd::Zero(P, P));
  lp.h.assign(static_cast<std::size_t>(n_units), Eigen::VectorXd::Zero(P));
  lp.s.assign(static_cast<std::size_t>(n_units), 0.0);
  lp.n.assign(static_cast<std::size_t>(n_units), 0.0);
  lp.prior_G = Eigen::MatrixXd::Zero(P, P);
  lp.prior_h = Eigen::VectorXd::Zero(P);
  lp.n_eff = std::max(2.0, n_eff);
  // Rank-one updates grouped by unit; rows with e == 0 and J == 0 add nothing.
  for (Eigen::Index i = 0; i < J.rows(); ++i) {
    const int u = unit[static_cast<std::size_t>(i)];
    if (u < 0 || e[i] == 0.0) continue;
    const auto k = static_cast<std::size_t>(u);
    lp.G[k].selfadjointView<Eigen::Lower>().rankUpdate(J.row(i).transpose());
    lp.h[k] += J.row(i).transpose() * e[i];
    lp.s[k] += e[i] * e[i];
    lp.n[k] += 1.0;
  }
  for (auto& g : lp.G) g = g.selfadjointView<Eigen::Lower>();
  double s = 0.0;
  for (double x : lp.s) s += x;
  lp.dispersion = std::max(1.0, s / lp.n_eff);
  return lp;
}

namespace {

struct Sums {
  Eigen::MatrixXd G;
  Eigen::VectorXd h;
  double s = 0.0, n = 0.0;
};

Sums sums(const LinearProblem& lp, const std::vector<double>& w, bool with_prior) {
  Sums t{Eigen::MatrixXd::Zero(lp.P(), lp.P()), Eigen::VectorXd::Zero(lp.P()), 0.0, 0.0};
  for (int u = 0; u < lp.units(); ++u) {
    const double k = w[static_cast<std::size_t>(u)];
    if (k == 0.0) continue;
    t.G += k * lp.G[static_cast<std::size_t>(u)];
    t.h += k * lp.h[static_cast<std::size_t>(u)];
    t.s += k * lp.s[static_cast<std::size_t>(u)];
    t.n += k * lp.n[static_cast<std::size_t>(u)];
  }
  if (with_prior) {
    t.G += lp.prior_G;
    t.h += lp.prior_h;
  }
  return t;
}

Eigen::MatrixXd sub(const Eigen::MatrixXd& G, const std::vector<int>& c) {
  Eigen::MatrixXd A(c.size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = 0; j < c.size(); ++j) A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = G(c[i], c[j]);
  return A;
}
Eigen::VectorXd sub(const Eigen::VectorXd& h, const std::vector<int>& c) {
  Eigen::VectorXd b(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) b[static_cast<Eigen::Index>(i)] = h[c[i]];
  return b;
}

SubsetFit solve(const Sums& t, const std::vector<int>& cols, double dispersion) {
  SubsetFit f;
  f.n = t.n;
  if (cols.empty()) {
    f.ok = true;
    f.rss = t.s;
    return f;
  }
  const Eigen::MatrixXd A = sub(t.G, cols);
  const Eigen::VectorXd b = sub(t.h, cols);
  Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 1e-12 * A.diagonal().array().abs().maxCoeff()).all())
    return f;
  f.beta = ldlt.solve(b);
  f.rss = std::max(0.0, t.s - b.dot(f.beta));
  const double s2 = dispersion;
  const Eigen::MatrixXd inv = ldlt.solve(Eigen::MatrixXd::Identity(A.rows(), A.cols()));
  f.sigma = (inv.diagonal() * s2).cwiseMax(0.0).cwiseSqrt();
  f.ok = std::isfinite(f.rss) && f.beta.allFinite();
  return f;
}

// Known-variance form on pre-weighted residuals: chi2 / dispersion + ln(n_eff) k.
double bic(const SubsetFit& f, const LinearProblem& lp, double weight_share, std::size_t k) {
  const double ne = std::max(2.0, lp.n_eff * weight_share);
  return f.rss / lp.dispersion + std::log(ne) * static_cast<double>(k);
}

double weightShare(const LinearProblem& lp, const std::vector<double>& w) {
  double a = 0.0, b = 0.0;
  for (std::size_t u = 0; u < lp.n.size(); ++u) {
    a += w[u] * lp.n[u];
    b += lp.n[u];
  }
  return b > 0 ? a / b : 1.0;
}

}  // namespace

SubsetFit fitSubset(const LinearProblem& lp, const std::vector<int>& cols, const std::vector<double>& w) {
  return solve(sums(lp, w, true), cols, lp.dispersion);
}

double crossValidationError(const LinearProblem& lp, const std::vector<int>& cols, int folds) {
  const int U = lp.units();
  const int K = std::max(2, std::min(folds, U));
  double err = 0.0;
  for (int f = 0; f < K; ++f) {
    std::vector<double> train(static_cast<std::size_t>(U), 1.0), test(static_cast<std::size_t>(U), 0.0);
    for (int u = f; u < U; u += K) {
      train[static_cast<std::size_t>(u)] = 0.0;
      test[static_cast<std::size_t>(u)] = 1.0;
    }
    const SubsetFit fit = solve(sums(lp, train, true), cols, lp.dispersion);
    const Sums ts = sums(lp, test, false);
    if (!fit.ok) return std::numeric_limits<double>::infinity();
    if (cols.empty()) {
      err += ts.s;
      continue;
    }
    const Eigen::MatrixXd Gt = sub(ts.G, cols);
    const Eigen::VectorXd ht = sub(ts.h, cols);
    err += ts.s - 2.0 * ht.dot(fit.beta) + fit.beta.dot(Gt * fit.beta);
  }
  return err;
}

SelectionResult forwardStepwise(const LinearProblem& lp, const std::vector<int>& candidates,
                                const std::vector<double>& w, const SelectionOptions& o, bool use_cv) {
  SelectionResult res;
  std::vector<int> cols;
  for (int j = 0; j < lp.n_nuisance; ++j) cols.push_back(j);
  const Sums all = sums(lp, w, true);
  SubsetFit cur = solve(all, cols, lp.dispersion);
  if (!cur.ok) return res;
  const double share = weightShare(lp, w);
  double curBic = bic(cur, lp, share, cols.size());
  double curCv = use_cv ? crossValidationError(lp, cols, o.folds) : 0.0;
  std::vector<int> left = candidates;
  while (!left.empty() && static_cast<int>(res.selected.size()) < o.max_terms) {
    int best = -1;
    StepRecord rec;
    double bestBic = curBic;
    SubsetFit bestFit;
    for (int c : left) {
      std::vector<int> trial = cols;
      trial.push_back(c);
      const SubsetFit f = solve(all, trial, lp.dispersion);
      if (!f.ok) continue;
      const double b = bic(f, lp, share, trial.size());
      const double t = std::abs(f.beta[f.beta.size() - 1]) / std::max(f.sigma[f.sigma.size() - 1], 1e-300);
      if (b - curBic > -o.bic_threshold || t < o.min_t) continue;
      if (b < bestBic) {
        bestBic = b;
        best = c;
        bestFit = f;
        rec.t_value = t;
      }
    }
    if (best < 0) break;
    std::vector<int> trial = cols;
    trial.push_back(best);
    rec.column = best;
    rec.delta_bic = bestBic - curBic;
    if (use_cv) {
      const double cv = crossValidationError(lp, trial, o.folds);
      rec.cv_before = curCv;
      rec.cv_after = cv;
      if (!(cv < curCv - o.min_cv_gain * lp.dispersion)) {
        // The best candidate does not predict held-out units: nothing else will.
        break;
      }
      curCv = cv;
    }
    cols = trial;
    cur = bestFit;
    curBic = bestBic;
    res.selected.push_back(best);
    res.steps.push_back(rec);
    left.erase(std::find(left.begin(), left.end(), best));
  }
  // Backward pass: a term that lost its significance once others came in goes.
  bool changed = true;
  while (changed && !res.selected.empty()) {
    changed = false;
    const SubsetFit f = solve(all, cols, lp.dispersion);
    if (!f.ok) break;
    for (std::size_t k = static_cast<std::size_t>(lp.n_nuisance); k < cols.size(); ++k) {
      const double t = std::abs(f.beta[static_cast<Eigen::Index>(k)]) / std::max(f.sigma[static_cast<Eigen::Index>(k)], 1e-300);
      if (t < o.min_t) {
        const int c = cols[k];
        cols.erase(cols.begin() + static_cast<std::ptrdiff_t>(k));
        const auto it = std::find(res.selected.begin(), res.selected.end(), c);
        res.steps.erase(res.steps.begin() + (it - res.selected.begin()));
        res.selected.erase(it);
        changed = true;
        break;
      }
    }
  }
  return res;
}

Inclusion inclusionStatistics(const LinearProblem& lp, const std::vector<int>& candidates, int replicates,
                              std::uint64_t seed, const SelectionOptions& o) {
  const auto C = static_cast<Eigen::Index>(candidates.size());
  Inclusion out{std::vector<double>(candidates.size(), 0.0), Eigen::MatrixXd::Zero(C, C)};
  const int U = lp.units();
  if (U < 2 || replicates <= 0) return out;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> pick(0, U - 1);
  for (int b = 0; b < replicates; ++b) {
    std::vector<double> w(static_cast<std::size_t>(U), 0.0);
    for (int k = 0; k < U; ++k) w[static_cast<std::size_t>(pick(rng))] += 1.0;
    const SelectionResult s = forwardStepwise(lp, candidates, w, o, false);
    std::vector<Eigen::Index> in;
    for (Eigen::Index c = 0; c < C; ++c)
      if (std::find(s.selected.begin(), s.selected.end(), candidates[static_cast<std::size_t>(c)]) != s.selected.end()) in.push_back(c);
    for (Eigen::Index i : in)
      for (Eigen::Index j : in) out.together(i, j) += 1.0;
  }
  out.together /= static_cast<double>(replicates);
  for (Eigen::Index c = 0; c < C; ++c) out.p[static_cast<std::size_t>(c)] = out.together(c, c);
  return out;
}

std::vector<double> inclusionProbabilities(const LinearProblem& lp, const std::vector<int>& candidates, int replicates,
                                           std::uint64_t seed, const SelectionOptions& o) {
  return inclusionStatistics(lp, candidates, replicates, seed, o).p;
}

std::vector<int> stlsq(const LinearProblem& lp, const std::vector<int>& candidates, double threshold) {
  std::vector<int> active = candidates;
  const std::vector<double> w(static_cast<std::size_t>(lp.units()), 1.0);
  for (int it = 0; it < 10; ++it) {
    std::vector<int> cols;
    for (int j = 0; j < lp.n_nuisance; ++j) cols.push_back(j);
    cols.insert(cols.end(), active.begin(), active.end());
    const SubsetFit f = fitSubset(lp, cols, w);
    if (!f.ok) break;
    std::vector<int> keep;
    for (std::size_t k = 0; k < active.size(); ++k)
      if (std::abs(f.beta[static_cast<Eigen::Index>(lp.n_nuisance + static_cast<int>(k))]) >= threshold)
        keep.push_back(active[k]);
    if (keep == active) break;
    active = keep;
  }
  return active;
}

Collinearity collinearity(const LinearProblem& lp, const std::vector<int>& candidates, const std::vector<int>& nuisance,
                          bool all_nuisance) {
  const std::vector<double> w(static_cast<std::size_t>(lp.units()), 1.0);
  const Sums t = sums(lp, w, false);
  std::vector<int> nu = nuisance;
  if (all_nuisance)
    for (int j = 0; j < lp.n_nuisance; ++j) nu.push_back(j);
  const Eigen::MatrixXd Gnn = sub(t.G, nu);
  const auto C = static_cast<Eigen::Index>(candidates.size());
  Eigen::MatrixXd Gcn(C, static_cast<Eigen::Index>(nu.size())), Gcc = sub(t.G, candidates);
  for (Eigen::Index i = 0; i < C; ++i)
    for (std::size_t j = 0; j < nu.size(); ++j) Gcn(i, static_cast<Eigen::Index>(j)) = t.G(candidates[static_cast<std::size_t>(i)], nu[j]);
  Eigen::MatrixXd S = Gcc;
  if (!nu.empty()) S -= Gcn * Gnn.ldlt().solve(Gcn.transpose());
  Collinearity c;
  c.correlation = Eigen::MatrixXd::Identity(C, C);
  c.nuisance_r2.resize(candidates.size());
  for (Eigen::Index i = 0; i < C; ++i) {
    c.nuisance_r2[static_cast<std::size_t>(i)] = Gcc(i, i) > 0 ? std::clamp(1.0 - S(i, i) / Gcc(i, i), 0.0, 1.0) : 1.0;
    for (Eigen::Index j = 0; j < C; ++j)
      if (i != j && S(i, i) > 0 && S(j, j) > 0) c.correlation(i, j) = S(i, j) / std::sqrt(S(i, i) * S(j, j));
  }
  return c;
}

}  // namespace auv::discrepancy
