#include "discrepancy/model_check.h"

#include <algorithm>
#include <numeric>

#include "discrepancy/held_out_scoring.h"
#include "discrepancy/held_term_findings.h"
#include "discrepancy/joint_refit.h"
#include "discrepancy/linearised_problem.h"
#include "discrepancy/noise_twin_test.h"
#include "discrepancy/residual_statistics.h"
#include "discrepancy/rms_and_localisation.h"
#include "discrepancy/term_acceptance.h"
#include "discrepancy/term_selection.h"
#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy {

namespace {

// Every term the model can show at all, restricted to `only_terms` when given.
std::vector<std::size_t> candidateTerms(const CheckModel& m, const ModelCheckOptions& o) {
  const auto& lib = termLibrary();
  std::vector<std::size_t> cand;
  for (std::size_t k = 0; k < kTermCount; ++k) {
    if (!m.applicable(k)) continue;
    if (!o.only_terms.empty() &&
        std::find(o.only_terms.begin(), o.only_terms.end(), std::string(lib[k].id)) == o.only_terms.end())
      continue;
    cand.push_back(k);
  }
  return cand;
}

}  // namespace

ModelCheckResult runModelCheck(const CheckModel& m, const ModelCheckOptions& o) {
  using namespace detail;
  ModelCheckResult R;
  R.model = m.description();
  R.reference_water = m.referenceWater();
  R.notes = m.notes();
  const SampleTable& S = m.samples();
  const std::size_t N = S.size();
  R.samples = N;
  const int U = S.unitCount();
  R.units = U;

  FitSetup s{m, m.equationChannels(), 0, 0, m.nuisanceScale(), m.nuisanceLower(), m.nuisanceUpper(), {}, m.priors(), {}, {}};
  s.C = s.eq.size();
  s.nN = static_cast<int>(s.nScale.size());
  R.nuisance_names = m.nuisanceNames();
  const std::vector<std::size_t> cand = candidateTerms(m, o);

  std::vector<std::uint32_t> all(N), fitRows;
  std::iota(all.begin(), all.end(), 0u);
  const std::size_t stride = std::max<std::size_t>(1, (N + o.max_fit_rows - 1) / std::max<std::size_t>(1, o.max_fit_rows));
  for (std::size_t i = 0; i < N; i += stride) fitRows.push_back(static_cast<std::uint32_t>(i));

  // --- 1. base fit: ballast state only --------------------------------------
  Params start;
  start.nuisance = m.nuisanceStart();
  s.sigma.assign(s.C, 1.0);
  s.eff.assign(s.C, 1.0);
  s.sigma = robustSigmas(s, residualsAt(s, start, fitRows));
  Fit base = fit(s, fitRows, {}, start);
  s.sigma = robustSigmas(s, residualsAt(s, base.params, fitRows));

  // --- 2. linearised problem, with the weights of the largest model ---------
  weightsFromLargestModel(s, S, linearise(s, base.params, cand, all));
  base = fit(s, fitRows, {}, base.params);
  R.base_params = base.params;
  R.net_buoyancy_base_kg = m.netBuoyancyKg(base.params);
  const Linearisation lin = linearise(s, base.params, cand, all);
  const LinearProblem lp = selectionProblem(s, S, lin, U, base.params, R.neff_ratio);

  // --- 3. identifiability, selection, ensembling -----------------------------
  const TermSelection ts = selectTerms(s, lp, cand, o, R);
  if (o.selection_only) return R;

  // --- 4. held-out simulation check ------------------------------------------
  const HeldOutScorer scorer(s, fitRows, base.params, R.warnings);
  TermAcceptance acc = acceptTerms(s, fitRows, scorer, ts, cand, base.params, o, R);
  if (o.noise_twin && !acc.found.empty()) testAgainstNoiseTwin(m, base.params, o, acc, R);

  // --- 5. final joint fit ------------------------------------------------------
  const Fit fin = jointRefit(s, fitRows, acc.accepted, base.params, acc.found, R);

  // A term accepted over a rival: the same fit with the rival instead.
  for (const MissingPhysics& mp : acc.found) {
    double total = mp.inclusion_probability;
    for (const TermRival& rv : mp.rivals) total += rv.inclusion_probability;
    for (const TermRival& rv : mp.rivals) {
      std::vector<std::size_t> swapped = acc.accepted;
      std::replace(swapped.begin(), swapped.end(), *findTerm(mp.id), *findTerm(rv.id));
      R.rival_fits.push_back({mp.id, rv.id, rv.inclusion_probability / total, fit(s, fitRows, swapped, base.params).params});
    }
  }

  // --- 6, 7. RMS before/after, fitted and held-out; localisation -------------
  reportRmsAndLocalisation(s, scorer, acc.accepted, base.params, fin.params, lin.raw, all, R);
  locateAcceptedTerms(s, fin.params, all, acc.found);
  reportHeldTermFindings(s, fitRows, acc.accepted, fin, all, acc.found, R);
  std::stable_sort(acc.found.begin(), acc.found.end(),
                   [](const MissingPhysics& a, const MissingPhysics& b) { return a.heldout_gain > b.heldout_gain; });
  R.missing_physics = acc.found;
  return R;
}

}  // namespace auv::discrepancy
