#include "discrepancy/term_acceptance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "discrepancy/held_shifts.h"
#include "discrepancy/residual_statistics.h"

namespace auv::discrepancy::detail {

namespace {

// Held-out equation error, each channel's mean square over its noise level.
double heldOutEquationCost(const FitSetup& s, const HeldOut& h) {
  double c = 0.0;
  for (std::size_t k = 0; k < s.C; ++k)
    if (h.eq_n[k] > 0) c += h.eq_sse[k] / h.eq_n[k] / (s.sigma[k] * s.sigma[k]);
  return c;
}

// The rivals of candidate k (options in model_check.h) and the share of
// replicates that picked k or one of them (union bound from the pair counts).
struct RivalSet {
  std::vector<TermRival> rivals;
  double group_inclusion = 0.0;
};

RivalSet rivalsOf(std::size_t k, const TermSelection& ts, const std::vector<std::size_t>& cand,
                  const std::vector<std::size_t>& accepted, const ModelCheckOptions& o) {
  RivalSet out;
  out.group_inclusion = ts.incl[k];
  for (std::size_t l = 0; l < cand.size(); ++l) {
    if (l == k || ts.incl[l] < o.min_rival_inclusion) continue;
    if (std::find(accepted.begin(), accepted.end(), cand[l]) != accepted.end()) continue;
    const double both = ts.together(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l));
    if (both > o.rival_max_together * std::min(ts.incl[k], ts.incl[l])) continue;
    out.rivals.push_back({std::string(termLibrary()[cand[l]].id), ts.incl[l]});
    out.group_inclusion += ts.incl[l] - both;
  }
  out.group_inclusion = std::min(out.group_inclusion, 1.0);
  return out;
}

// One held-out comparison: the accepted model (`cur`, scored on the same
// horizons) against it plus the trial term.
struct HeldOutTrial {
  HeldOut cur, ho;
  bool short_horizons = false, pass = false, sim_better = false;
  double before = 0.0, after = 0.0, eq_before = 0.0, eq_after = 0.0;
};

HeldOutTrial heldOutTrial(const FitSetup& s, const HeldOutScorer& scorer, HeldOut cur, const std::vector<std::size_t>& trial,
                          const Params& start, bool short_horizons, const ModelCheckOptions& o) {
  HeldOutTrial t;
  t.short_horizons = short_horizons;
  t.cur = std::move(cur);
  t.ho = scorer.score(trial, start, short_horizons);
  t.before = scorer.cost(t.cur, short_horizons);
  t.after = scorer.cost(t.ho, short_horizons);
  t.eq_before = heldOutEquationCost(s, t.cur);
  t.eq_after = heldOutEquationCost(s, t.ho);
  t.sim_better = t.after < t.before * (1.0 - o.min_sim_gain);
  const bool eqBetter = t.after <= t.before * (1.0 + o.max_sim_loss) && t.eq_after < t.eq_before * (1.0 - o.min_eq_gain);
  t.pass = t.sim_better || eqBetter;
  return t;
}

// The trial term's fitted increment against what the held calibration could
// put into it: the formal sigma and the spread over the held constants, each
// one of its sigmas up (held_shifts.h), in quadrature.
struct CalibrationTest {
  Fit full;
  double value = 0.0, formal = 0.0, spread = 0.0;
  double z() const { return std::abs(value) / std::max(std::hypot(formal, spread), 1e-300); }
};

CalibrationTest calibrationTest(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const std::vector<std::size_t>& trial,
                                const Params& start) {
  CalibrationTest t;
  const std::size_t term = trial.back();
  t.full = fit(s, fitRows, trial, start);
  t.value = t.full.params.terms[term];
  t.formal = t.full.sigma[s.nN + static_cast<Eigen::Index>(trial.size() - 1)];
  const HeldShifts h = heldShifts(s, fitRows, trial, t.full.params);
  double var = 0.0;
  for (const Params& p : h.shifted) var += std::pow(p.terms[term] - h.unshifted.terms[term], 2);
  t.spread = std::sqrt(var);
  return t;
}

}  // namespace

TermAcceptance acceptTerms(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const HeldOutScorer& scorer,
                           const TermSelection& ts, const std::vector<std::size_t>& cand, const Params& base,
                           const ModelCheckOptions& o, ModelCheckResult& R) {
  const auto& lib = termLibrary();
  const std::vector<Channel>& simCh = scorer.channels();
  const std::size_t SC = simCh.size();
  const SelectionResult& sel = ts.sel;
  const std::vector<double>& incl = ts.incl;
  TermAcceptance out;
  std::vector<std::size_t>& accepted = out.accepted;
  HeldOut hoCur = scorer.base();
  for (std::size_t step = 0; step < sel.selected.size(); ++step) {
    const std::size_t k = static_cast<std::size_t>(sel.selected[step] - s.nN);
    const std::size_t term = cand[k];
    CandidateReport& c = R.candidates[k];
    char buf[200];
    RivalSet rs;
    if (incl[k] < o.min_inclusion && incl[k] >= o.min_inclusion_with_rivals) rs = rivalsOf(k, ts, cand, accepted, o);
    if (incl[k] < o.min_inclusion && (rs.rivals.empty() || rs.group_inclusion < o.min_inclusion)) {
      std::snprintf(buf, sizeof buf, "selected on all data but only in %.0f %% of bootstrap replicates (< %.0f %%)",
                    100 * incl[k], 100 * o.min_inclusion);
      c.status = buf;
      continue;
    }
    std::vector<std::size_t> trial = accepted;
    trial.push_back(term);
    Params st = base;
    for (std::size_t a : accepted) st.terms[a] = R.accepted[a];
    // The whole-log replay first; a transient term (PhysicsTerm::transient)
    // that fails it is judged again on short replays, against the accepted
    // model on the same horizons.
    HeldOutTrial t = heldOutTrial(s, scorer, hoCur, trial, st, false, o);
    if (!t.pass && lib[term].transient) {
      HeldOutTrial ts2 = heldOutTrial(s, scorer, scorer.score(accepted, st, true), trial, st, true, o);
      // The second chance also asks the other half's equation error, which
      // the term was fitted to, not to get worse: a quadratic pitch damping
      // standing in for the autopilot's answer to sensor noise (drawn truth
      // 1101, none in it) gained 1.1 % in short replays and lost 0.07 % there.
      if (ts2.pass && ts2.eq_after <= ts2.eq_before) t = std::move(ts2);
    }
    const bool shortH = t.short_horizons;
    const HeldOut& cur = t.cur;
    const HeldOut& ho = t.ho;
    if (!t.pass) {
      std::snprintf(buf, sizeof buf,
                    "improves the equation error but not the held-out simulation error%s (cost %.4g -> %.4g; held-out "
                    "equation error %.4g -> %.4g)",
                    lib[term].transient ? ", whole or in short replays" : "", t.before, t.after, t.eq_before, t.eq_after);
      c.status = buf;
      continue;
    }
    // Held-out halves share the held calibration, so a term that only stands
    // in for a held group one sigma off passes them; it must also stand out
    // from that (on drawn HUGIN truths the false terms were buoyancy laws).
    const CalibrationTest ct = calibrationTest(s, fitRows, trial, st);
    // A fit pinned at the plausible range's end stands in for something else
    // (seen: M_|q|q x6 on a control log); there its spread cannot be measured.
    const double edge = 1e-3 * lib[term].typical;
    const auto [lower, upper] = s.m.termRange(term);
    if (ct.value <= lower + edge || ct.value >= upper - edge) {
      std::snprintf(buf, sizeof buf, "fitted at the end of its plausible range (%.3g, range %.3g to %.3g)",
                    ct.value * lib[term].display_scale, lower * lib[term].display_scale, upper * lib[term].display_scale);
      c.status = buf;
      continue;
    }
    if (ct.z() < o.min_calibration_z) {
      const double d = std::abs(lib[term].display_scale);
      std::snprintf(buf, sizeof buf,
                    "within what the held calibration's uncertainty can put into it (%.3g +- %.2g formal, +- %.2g from "
                    "the held constants: %.1f sigma < %.1f)",
                    ct.value * lib[term].display_scale, ct.formal * d, ct.spread * d, ct.z(), o.min_calibration_z);
      c.status = buf;
      continue;
    }
    const bool simBetter = t.sim_better;
    const double before = t.before, after = t.after, eqBefore = t.eq_before, eqAfter = t.eq_after;
    c.status = "accepted";
    MissingPhysics mp;
    mp.rivals = rs.rivals;
    for (const TermRival& rv : rs.rivals) {
      std::snprintf(buf, sizeof buf, " (in %.0f %% of bootstrap replicates %s was picked instead)", 100 * rv.inclusion_probability,
                    rv.id.c_str());
      c.status += buf;
    }
    mp.id = lib[term].id;
    mp.unit = lib[term].unit;
    mp.inclusion_probability = incl[k];
    mp.delta_bic = sel.steps[step].delta_bic;
    mp.t_value = sel.steps[step].t_value;
    mp.heldout_gain = simBetter ? 1.0 - after / before : 1.0 - eqAfter / eqBefore;
    if (ho.fits.size() == 2)
      mp.split_half_sigma = 0.5 * std::abs(ho.fits[0].terms[term] - ho.fits[1].terms[term]) * lib[term].display_scale;
    // The channel the term helps most (relative to the base error).
    double bestGain = -std::numeric_limits<double>::infinity();
    for (std::size_t ch = 0; ch < SC; ++ch) {
      if (!(cur.sim_n[ch] > 0)) continue;
      const double g = (cur.sim_sse[ch] / cur.sim_n[ch] - ho.sim_sse[ch] / ho.sim_n[ch]) / scorer.reference(ch, shortH);
      if (g > bestGain) {
        bestGain = g;
        mp.channel = simCh[ch];
        mp.rms_before = rmsOf(cur.sim_sse[ch], cur.sim_n[ch]) * channelDisplayScale(simCh[ch]);
        mp.rms_after = rmsOf(ho.sim_sse[ch], ho.sim_n[ch]) * channelDisplayScale(simCh[ch]);
      }
    }
    for (std::size_t k2 = 0; k2 < cur.prior_z2.size(); ++k2)
      if (s.priors[k2].measured && ho.prior_z2[k2] < cur.prior_z2[k2] && cur.prior_z2[k2] > 4.0)
        mp.evidence = "the flight data alone cannot separate it from " + R.nuisance_names[static_cast<std::size_t>(s.priors[k2].index)] +
                      "; the independent measurement of that (prior) does: without the term the fit is " +
                      std::to_string(static_cast<int>(std::lround(std::sqrt(cur.prior_z2[k2])))) + " sigma from it";
    for (std::size_t l = 0; l < cand.size(); ++l)
      if (l != k && std::abs(ts.coll.correlation(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l))) >= o.collinear_threshold)
        mp.confused_with.emplace_back(lib[cand[l]].id);
    for (const TermRival& rv : rs.rivals)
      if (std::find(mp.confused_with.begin(), mp.confused_with.end(), rv.id) == mp.confused_with.end()) mp.confused_with.push_back(rv.id);
    out.found.push_back(mp);
    accepted.push_back(term);
    R.accepted = ct.full.params.terms;  // provisional values for the next step's start
    hoCur = shortH ? scorer.score(accepted, st) : ho;  // the next term is judged on the whole log again
  }
  return out;
}

}  // namespace auv::discrepancy::detail
