#include "discrepancy/term_selection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "discrepancy/identifiability.h"

namespace auv::discrepancy::detail {

TermSelection selectTerms(const FitSetup& s, const LinearProblem& lp, const std::vector<std::size_t>& cand,
                          const ModelCheckOptions& o, ModelCheckResult& R) {
  const auto& lib = termLibrary();
  const int U = lp.units();
  TermSelection ts;
  std::vector<int> candCols;
  for (std::size_t k = 0; k < cand.size(); ++k) candCols.push_back(s.nN + static_cast<int>(k));
  ts.coll = collinearity(lp, candCols);
  const Collinearity& coll = ts.coll;
  // A prior (e.g. CG y from a roll test) can break a degeneracy with the
  // nuisance: judge those candidates against the nuisance without the prior.
  Collinearity collFree = coll;
  if (!s.priors.empty()) {
    std::vector<int> free;
    for (int j = 0; j < s.nN; ++j)
      if (std::none_of(s.priors.begin(), s.priors.end(), [j](const NuisancePrior& q) { return q.index == j; }))
        free.push_back(j);
    collFree = collinearity(lp, candCols, free, false);
  }
  std::vector<int> eligible;
  std::vector<bool> excluded(cand.size(), false);
  for (std::size_t k = 0; k < cand.size(); ++k) {
    excluded[k] = coll.nuisance_r2[k] >= o.degenerate_r2 && collFree.nuisance_r2[k] >= o.degenerate_r2;
    if (!excluded[k]) eligible.push_back(candCols[k]);
  }
  const std::vector<double> ones(static_cast<std::size_t>(U), 1.0);
  ts.sel = forwardStepwise(lp, eligible, ones, o.selection, true);
  const Inclusion inclEligible = inclusionStatistics(lp, eligible, o.bootstrap_replicates, o.seed, o.selection);
  ts.incl.assign(cand.size(), 0.0);
  const auto K = static_cast<Eigen::Index>(cand.size());
  ts.together = Eigen::MatrixXd::Zero(K, K);
  for (std::size_t e = 0; e < eligible.size(); ++e) {
    const auto k = static_cast<Eigen::Index>(eligible[e] - s.nN);
    ts.incl[static_cast<std::size_t>(k)] = inclEligible.p[e];
    for (std::size_t f = 0; f < eligible.size(); ++f)
      ts.together(k, static_cast<Eigen::Index>(eligible[f] - s.nN)) =
          inclEligible.together(static_cast<Eigen::Index>(e), static_cast<Eigen::Index>(f));
  }
  for (int c : stlsq(lp, eligible, o.stlsq_threshold)) R.stlsq_selected.emplace_back(lib[cand[static_cast<std::size_t>(c - s.nN)]].id);
  std::vector<int> nuisanceCols(static_cast<std::size_t>(s.nN));
  std::iota(nuisanceCols.begin(), nuisanceCols.end(), 0);
  R.candidates.resize(cand.size());
  for (std::size_t k = 0; k < cand.size(); ++k) {
    CandidateReport& c = R.candidates[k];
    const PhysicsTerm& t = lib[cand[k]];
    c.id = t.id;
    c.inclusion_probability = ts.incl[k];
    c.nuisance_r2 = coll.nuisance_r2[k];
    std::vector<int> cols = nuisanceCols;
    cols.push_back(candCols[k]);
    const SubsetFit f = fitSubset(lp, cols, ones);
    if (f.ok) {
      const double b = f.beta[f.beta.size() - 1], sg = f.sigma[f.sigma.size() - 1];
      c.value = b * t.typical * t.display_scale;
      c.sigma = sg * t.typical * t.display_scale;
      c.t_value = std::abs(b) / std::max(sg, 1e-300);
    }
    c.status = excluded[k] ? "not identifiable from this log: its effect is indistinguishable from the ballast state"
                           : "not selected: no significant, cross-validated improvement of the equation error";
    if (coll.nuisance_r2[k] >= o.collinear_threshold && collFree.nuisance_r2[k] >= o.collinear_threshold) {
      IdentifiabilityIssue is{std::string(t.id), "ballast_state", std::sqrt(coll.nuisance_r2[k]), ""};
      is.message = std::string(t.id) + " cannot be told apart from the ballast state (net buoyancy" +
                   (s.m.hasCg() ? ", CG" : ", Cd0") + ") by this log " + separationAdvice(t.id, "ballast_state");
      R.identifiability.push_back(is);
    }
    for (std::size_t l = k + 1; l < cand.size(); ++l) {
      const double r = coll.correlation(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l));
      if (std::abs(r) >= o.collinear_threshold) {
        const PhysicsTerm& u = lib[cand[l]];
        IdentifiabilityIssue is{std::string(t.id), std::string(u.id), r, ""};
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3f", r);
        is.message = std::string(t.id) + " and " + std::string(u.id) + " cannot be told apart by this log (regressor correlation " +
                     buf + " after the ballast state) " + separationAdvice(t.id, u.id);
        R.identifiability.push_back(is);
      }
    }
  }
  return ts;
}

}  // namespace auv::discrepancy::detail
