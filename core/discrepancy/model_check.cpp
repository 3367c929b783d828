#include "discrepancy/model_check.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "common/units.h"
#include "discrepancy/identifiability.h"
#include "discrepancy/levenberg_marquardt.h"

namespace auv::discrepancy {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Smallest RMS a channel is scored against, so that a channel the base model
// already matches cannot dominate the relative simulation cost.
double channelFloor(Channel c) {
  switch (c) {
    case Channel::kVerticalVelocity: return 1e-3;
    case Channel::kDepth: return 0.01;
    case Channel::kPitch:
    case Channel::kRoll: return units::degToRad(0.01);
    case Channel::kSpeed: return 1e-3;
    default: return 1e-6;
  }
}

struct Setup {
  const CheckModel& m;
  std::vector<Channel> eq;
  std::size_t C = 0;
  int nN = 0;
  Eigen::VectorXd nScale, nLo, nHi;
  std::vector<double> sigma;  // per equation channel
  std::vector<NuisancePrior> priors;
  std::vector<double> eff;    // per channel: effective / actual sample size (AR(1) of the residuals)
  double weight(std::size_t c) const { return std::sqrt(eff[c]) / sigma[c]; }
};

Params toParams(const Setup& s, const Eigen::VectorXd& x, const std::vector<std::size_t>& terms) {
  Params p;
  p.nuisance = x.head(s.nN);
  for (std::size_t k = 0; k < terms.size(); ++k) p.terms[terms[k]] = x[s.nN + static_cast<Eigen::Index>(k)];
  return p;
}

Eigen::VectorXd fromParams(const Setup& s, const Params& p, const std::vector<std::size_t>& terms) {
  Eigen::VectorXd x(s.nN + static_cast<Eigen::Index>(terms.size()));
  x.head(s.nN) = p.nuisance;
  for (std::size_t k = 0; k < terms.size(); ++k) x[s.nN + static_cast<Eigen::Index>(k)] = p.terms[terms[k]];
  return x;
}

LmProblem makeProblem(const Setup& s, const std::vector<std::uint32_t>& rows, const std::vector<std::size_t>& terms) {
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
    p.lower[j] = t.lower;
    p.upper[j] = t.upper;
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

struct Fit {
  Params params;
  Eigen::VectorXd x, sigma;
  double cost = 0.0;
};

Fit fit(const Setup& s, const std::vector<std::uint32_t>& rows, const std::vector<std::size_t>& terms, const Params& start) {
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

std::vector<double> residualsAt(const Setup& s, const Params& p, const std::vector<std::uint32_t>& rows) {
  std::vector<double> out(rows.size() * s.C);
  s.m.equationError(p, rows, out.data());
  return out;
}

double mad(std::vector<double> v) {
  if (v.empty()) return kNaN;
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  const double med = *mid;
  for (double& x : v) x = std::abs(x - med);
  std::nth_element(v.begin(), mid, v.end());
  return 1.4826 * *mid;
}

std::vector<double> robustSigmas(const Setup& s, const std::vector<double>& r) {
  std::vector<double> sig(s.C);
  for (std::size_t c = 0; c < s.C; ++c) {
    std::vector<double> v;
    for (std::size_t i = c; i < r.size(); i += s.C)
      if (std::isfinite(r[i])) v.push_back(r[i]);
    const double m = mad(v);
    sig[c] = std::max(std::isfinite(m) ? m : 1.0, channelFloor(s.eq[c]));
  }
  return sig;
}

// Effective / actual sample size per channel from the lag-1
// autocorrelation of the residuals within blocks (AR(1): (1 - r) / (1 + r)).
std::vector<double> effectiveShares(const Setup& s, const SampleTable& S, const std::vector<double>& r) {
  std::vector<double> out(s.C, 1.0);
  for (std::size_t c = 0; c < s.C; ++c) {
    double num = 0.0, den = 0.0, mean = 0.0, n = 0.0;
    for (std::size_t i = 0; i < S.size(); ++i)
      if (std::isfinite(r[i * s.C + c])) {
        mean += r[i * s.C + c];
        n += 1.0;
      }
    if (n < 3) continue;
    mean /= n;
    for (std::size_t i = 0; i + 1 < S.size(); ++i) {
      const double a = r[i * s.C + c], b = r[(i + 1) * s.C + c];
      if (S.block[i] != S.block[i + 1] || !std::isfinite(a) || !std::isfinite(b)) continue;
      num += (a - mean) * (b - mean);
    }
    for (std::size_t i = 0; i < S.size(); ++i) {
      const double a = r[i * s.C + c];
      if (std::isfinite(a)) den += (a - mean) * (a - mean);
    }
    const double rho = den > 0 ? std::clamp(num / den, 0.0, 0.999) : 0.0;
    out[c] = (1.0 - rho) / (1.0 + rho);
  }
  return out;
}

struct HeldOut {
  std::vector<double> sim_sse, eq_sse;
  std::vector<double> sim_n, eq_n;
  std::vector<double> prior_z2;  // per prior: squared standardised distance of the fit from it (mean of the halves)
  std::vector<Params> fits;      // fitted on half 0 and on half 1
};

// Two halves of the units: fit on one, score the whole-log simulation and the
// equation error on the other; both ways.
HeldOut heldOut(const Setup& s, const std::vector<std::vector<std::uint32_t>>& halfFitRows,
                const std::vector<int>& halfOfRow, const std::vector<std::size_t>& terms, const Params& start,
                std::size_t simC) {
  HeldOut h;
  h.sim_sse.assign(simC, 0.0);
  h.sim_n.assign(simC, 0.0);
  h.eq_sse.assign(s.C, 0.0);
  h.eq_n.assign(s.C, 0.0);
  h.prior_z2.assign(s.priors.size(), 0.0);
  const std::size_t N = halfOfRow.size();
  std::vector<std::uint32_t> all(N);
  std::iota(all.begin(), all.end(), 0u);
  for (int half = 0; half < 2; ++half) {
    const Fit f = fit(s, halfFitRows[static_cast<std::size_t>(half)], terms, start);
    h.fits.push_back(f.params);
    // A prior is an independent measurement (e.g. the roll test's CG y): the
    // model fitted to the flight data must reproduce it, like any held-out data.
    for (std::size_t k = 0; k < s.priors.size(); ++k) {
      const double z = (f.params.nuisance[s.priors[k].index] - s.priors[k].mean) / s.priors[k].sigma;
      h.prior_z2[k] += 0.5 * z * z;
    }
    std::vector<double> sim;
    s.m.simulationError(f.params, sim);
    const std::vector<double> eq = residualsAt(s, f.params, all);
    for (std::size_t i = 0; i < N; ++i) {
      if (halfOfRow[i] == half) continue;
      for (std::size_t c = 0; c < simC; ++c) {
        const double v = sim[i * simC + c];
        if (std::isfinite(v)) {
          h.sim_sse[c] += v * v;
          h.sim_n[c] += 1.0;
        }
      }
      for (std::size_t c = 0; c < s.C; ++c) {
        const double v = eq[i * s.C + c];
        if (std::isfinite(v)) {
          h.eq_sse[c] += v * v;
          h.eq_n[c] += 1.0;
        }
      }
    }
  }
  return h;
}

double rmsOf(double sse, double n) { return n > 0 ? std::sqrt(sse / n) : kNaN; }

std::vector<double> channelColumn(const std::vector<double>& v, std::size_t C, std::size_t c) {
  std::vector<double> out(v.size() / C);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = v[i * C + c];
  return out;
}

void rmsPerChannel(const std::vector<double>& v, std::size_t C, std::vector<double>& sse, std::vector<double>& n) {
  sse.assign(C, 0.0);
  n.assign(C, 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isfinite(v[i])) {
      sse[i % C] += v[i] * v[i];
      n[i % C] += 1.0;
    }
}

}  // namespace

ModelCheckResult runModelCheck(const CheckModel& m, const ModelCheckOptions& o) {
  ModelCheckResult R;
  R.model = m.description();
  R.notes = m.notes();
  const SampleTable& S = m.samples();
  const std::size_t N = S.size();
  R.samples = N;
  const int U = S.unitCount();
  R.units = U;

  Setup s{m, m.equationChannels(), 0, 0, m.nuisanceScale(), m.nuisanceLower(), m.nuisanceUpper(), {}, m.priors(), {}};
  s.C = s.eq.size();
  s.nN = static_cast<int>(s.nScale.size());
  R.nuisance_names = m.nuisanceNames();
  const auto& lib = termLibrary();

  std::vector<std::size_t> cand;
  for (std::size_t k = 0; k < kTermCount; ++k) {
    if (!m.applicable(k)) continue;
    if (!o.only_terms.empty() &&
        std::find(o.only_terms.begin(), o.only_terms.end(), std::string(lib[k].id)) == o.only_terms.end())
      continue;
    cand.push_back(k);
  }

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

  // --- 2. linearised problem ---------------------------------------------------
  const Eigen::Index P = s.nN + static_cast<Eigen::Index>(cand.size());
  const auto NR = static_cast<Eigen::Index>(N * s.C);
  std::vector<double> e0raw;
  Eigen::VectorXd e0(NR);
  Eigen::MatrixXd J(NR, P);
  auto linearise = [&]() {
    e0raw = residualsAt(s, base.params, all);
    for (Eigen::Index i = 0; i < NR; ++i) {
      const double v = e0raw[static_cast<std::size_t>(i)];
      e0[i] = std::isfinite(v) ? v * s.weight(static_cast<std::size_t>(i) % s.C) : 0.0;
    }
    auto column = [&](const Params& plus, const Params& minus, double h, Eigen::Index col) {
      const std::vector<double> a = residualsAt(s, plus, all), b = residualsAt(s, minus, all);
      for (Eigen::Index i = 0; i < NR; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const double d = -(a[k] - b[k]) / (2.0 * h);  // d(model)/d(parameter in its scale)
        J(i, col) = std::isfinite(d) ? d * s.weight(k % s.C) : 0.0;
      }
    };
    for (int j = 0; j < s.nN; ++j) {
      Params a = base.params, b = base.params;
      a.nuisance[j] += 1e-2 * s.nScale[j];
      b.nuisance[j] -= 1e-2 * s.nScale[j];
      column(a, b, 1e-2, j);
    }
    for (std::size_t k = 0; k < cand.size(); ++k) {
      Params a = base.params, b = base.params;
      a.terms[cand[k]] = lib[cand[k]].typical;
      b.terms[cand[k]] = -lib[cand[k]].typical;
      column(a, b, 1.0, s.nN + static_cast<Eigen::Index>(k));
    }
  };
  linearise();
  // Noise level and effective sample size per channel from the residuals of
  // the largest model (every candidate in): the base residuals still hold the
  // missing effect, whose own autocorrelation would understate n_eff.
  {
    Eigen::MatrixXd A = J.transpose() * J;
    const double ridge = 1e-9 * std::max(1e-300, A.trace() / static_cast<double>(P));
    A.diagonal().array() += ridge;
    const Eigen::VectorXd beta = A.ldlt().solve(J.transpose() * e0);
    const Eigen::VectorXd ef = e0 - J * beta;
    std::vector<double> full(static_cast<std::size_t>(NR));
    for (Eigen::Index i = 0; i < NR; ++i) {
      const auto k = static_cast<std::size_t>(i);
      full[k] = std::isfinite(e0raw[k]) ? ef[i] / s.weight(k % s.C) : kNaN;
    }
    s.sigma = robustSigmas(s, full);
    s.eff = effectiveShares(s, S, full);
  }
  base = fit(s, fitRows, {}, base.params);
  R.base_params = base.params;
  R.net_buoyancy_base_kg = m.netBuoyancyKg(base.params);
  linearise();
  double nEff = 0.0, nAll = 0.0;
  for (std::size_t i = 0; i < e0raw.size(); ++i)
    if (std::isfinite(e0raw[i])) {
      nEff += s.eff[i % s.C];
      nAll += 1.0;
    }
  R.neff_ratio = nAll > 0 ? nEff / nAll : 1.0;
  std::vector<int> unitOfResidual(static_cast<std::size_t>(NR));
  for (std::size_t i = 0; i < static_cast<std::size_t>(NR); ++i) unitOfResidual[i] = S.unit[i / s.C];
  LinearProblem lp = buildLinearProblem(J, e0, unitOfResidual, U, s.nN, nEff);
  for (const NuisancePrior& q : s.priors) {
    const double a = s.nScale[q.index] / q.sigma;
    lp.prior_G(q.index, q.index) += a * a;
    lp.prior_h[q.index] += a * (q.mean - base.params.nuisance[q.index]) / q.sigma;
  }

  // --- 3. identifiability, selection, ensembling ---------------------------------
  std::vector<int> candCols;
  for (std::size_t k = 0; k < cand.size(); ++k) candCols.push_back(s.nN + static_cast<int>(k));
  const Collinearity coll = collinearity(lp, candCols);
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
  const SelectionResult sel = forwardStepwise(lp, eligible, ones, o.selection, true);
  const std::vector<double> inclEligible = inclusionProbabilities(lp, eligible, o.bootstrap_replicates, o.seed, o.selection);
  std::vector<double> incl(cand.size(), 0.0);
  for (std::size_t e = 0; e < eligible.size(); ++e) incl[static_cast<std::size_t>(eligible[e] - s.nN)] = inclEligible[e];
  for (int c : stlsq(lp, eligible, o.stlsq_threshold)) R.stlsq_selected.emplace_back(lib[cand[static_cast<std::size_t>(c - s.nN)]].id);
  std::vector<int> nuisanceCols(static_cast<std::size_t>(s.nN));
  std::iota(nuisanceCols.begin(), nuisanceCols.end(), 0);
  R.candidates.resize(cand.size());
  for (std::size_t k = 0; k < cand.size(); ++k) {
    CandidateReport& c = R.candidates[k];
    const PhysicsTerm& t = lib[cand[k]];
    c.id = t.id;
    c.inclusion_probability = incl[k];
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
                   (m.hasCg() ? ", CG" : ", Cd0") + ") by this log " + separationAdvice(t.id, "ballast_state");
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

  // --- 4. held-out simulation check ----------------------------------------------
  const std::vector<Channel> simCh = m.simulationChannels();
  const std::size_t SC = simCh.size();
  std::vector<int> halfOfRow(N);
  if (U >= 2) {
    for (std::size_t i = 0; i < N; ++i) halfOfRow[i] = S.unit[i] % 2;
  } else {
    const double tm = 0.5 * (S.t.front() + S.t.back());
    for (std::size_t i = 0; i < N; ++i) halfOfRow[i] = S.t[i] < tm ? 0 : 1;
    R.warnings.push_back("the log has a single dive/leg: held-out checks use its two halves in time");
  }
  std::vector<std::vector<std::uint32_t>> halfFit(2);
  for (std::uint32_t i : fitRows) halfFit[static_cast<std::size_t>(halfOfRow[i])].push_back(i);

  const HeldOut hoBase = heldOut(s, halfFit, halfOfRow, {}, base.params, SC);
  std::vector<double> simRef(SC);
  for (std::size_t c = 0; c < SC; ++c) {
    const double f = channelFloor(simCh[c]);
    simRef[c] = std::max(hoBase.sim_n[c] > 0 ? hoBase.sim_sse[c] / hoBase.sim_n[c] : 0.0, f * f);
  }
  auto simCost = [&](const HeldOut& h) {
    double c = 0.0;
    for (std::size_t k = 0; k < SC; ++k)
      if (h.sim_n[k] > 0) c += h.sim_sse[k] / h.sim_n[k] / simRef[k];
    for (std::size_t k = 0; k < h.prior_z2.size(); ++k) c += std::max(1.0, h.prior_z2[k]) / std::max(1.0, hoBase.prior_z2[k]);
    return c;
  };
  std::vector<std::size_t> accepted;
  HeldOut hoCur = hoBase;
  std::vector<MissingPhysics> found;
  for (std::size_t step = 0; step < sel.selected.size(); ++step) {
    const std::size_t k = static_cast<std::size_t>(sel.selected[step] - s.nN);
    const std::size_t term = cand[k];
    CandidateReport& c = R.candidates[k];
    char buf[160];
    if (incl[k] < o.min_inclusion) {
      std::snprintf(buf, sizeof buf, "selected on all data but only in %.0f %% of bootstrap replicates (< %.0f %%)",
                    100 * incl[k], 100 * o.min_inclusion);
      c.status = buf;
      continue;
    }
    std::vector<std::size_t> trial = accepted;
    trial.push_back(term);
    Params st = base.params;
    for (std::size_t a : accepted) st.terms[a] = R.accepted[a];
    const HeldOut ho = heldOut(s, halfFit, halfOfRow, trial, st, SC);
    const double before = simCost(hoCur), after = simCost(ho);
    if (!(after < before * (1.0 - o.min_sim_gain))) {
      std::snprintf(buf, sizeof buf, "improves the equation error but not the held-out simulation error (cost %.4g -> %.4g)",
                    before, after);
      c.status = buf;
      continue;
    }
    c.status = "accepted";
    MissingPhysics mp;
    mp.id = lib[term].id;
    mp.unit = lib[term].unit;
    mp.inclusion_probability = incl[k];
    mp.delta_bic = sel.steps[step].delta_bic;
    mp.t_value = sel.steps[step].t_value;
    mp.heldout_gain = 1.0 - after / before;
    // The channel the term helps most (relative to the base error).
    double bestGain = -std::numeric_limits<double>::infinity();
    for (std::size_t ch = 0; ch < SC; ++ch) {
      if (!(hoCur.sim_n[ch] > 0)) continue;
      const double g = (hoCur.sim_sse[ch] / hoCur.sim_n[ch] - ho.sim_sse[ch] / ho.sim_n[ch]) / simRef[ch];
      if (g > bestGain) {
        bestGain = g;
        mp.channel = simCh[ch];
        mp.rms_before = rmsOf(hoCur.sim_sse[ch], hoCur.sim_n[ch]) * channelDisplayScale(simCh[ch]);
        mp.rms_after = rmsOf(ho.sim_sse[ch], ho.sim_n[ch]) * channelDisplayScale(simCh[ch]);
      }
    }
    for (std::size_t k2 = 0; k2 < hoCur.prior_z2.size(); ++k2)
      if (ho.prior_z2[k2] < hoCur.prior_z2[k2] && hoCur.prior_z2[k2] > 4.0)
        mp.evidence = "the flight data alone cannot separate it from " + R.nuisance_names[static_cast<std::size_t>(s.priors[k2].index)] +
                      "; the independent measurement of that (prior) does: without the term the fit is " +
                      std::to_string(static_cast<int>(std::lround(std::sqrt(hoCur.prior_z2[k2])))) + " sigma from it";
    for (std::size_t l = 0; l < cand.size(); ++l)
      if (l != k && std::abs(coll.correlation(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l))) >= o.collinear_threshold)
        mp.confused_with.emplace_back(lib[cand[l]].id);
    found.push_back(mp);
    accepted.push_back(term);
    // Provisional value for the next step's start.
    const Fit f = fit(s, fitRows, accepted, st);
    R.accepted = f.params.terms;
    hoCur = ho;
  }

  // --- 5. final joint fit ----------------------------------------------------------
  Params st = base.params;
  for (std::size_t a : accepted) st.terms[a] = R.accepted[a];
  const Fit fin = fit(s, fitRows, accepted, st);
  R.final_params = fin.params;
  R.accepted = TermValues{};
  for (std::size_t a : accepted) R.accepted[a] = fin.params.terms[a];
  for (auto& mp : found) {
    const std::size_t term = *findTerm(mp.id);
    const auto pos = std::find(accepted.begin(), accepted.end(), term) - accepted.begin();
    mp.value = fin.params.terms[term] * lib[term].display_scale;
    mp.sigma = fin.sigma[s.nN + pos] * lib[term].display_scale;
  }
  for (int j = 0; j < s.nN; ++j) {
    R.nuisance.push_back(fin.params.nuisance[j]);
    R.nuisance_sigma.push_back(fin.sigma[j]);
  }
  R.net_buoyancy_kg = m.netBuoyancyKg(fin.params);
  {
    // Sigma of the reported net buoyancy by finite differences over the nuisance.
    double var = 0.0;
    for (int j = 0; j < s.nN; ++j) {
      Params q = fin.params;
      q.nuisance[j] += fin.sigma[j];
      const double d = m.netBuoyancyKg(q) - R.net_buoyancy_kg;
      var += d * d;
    }
    R.net_buoyancy_sigma_kg = std::sqrt(var);
  }
  if (m.hasCg()) {
    R.has_cg = true;
    R.cg_x_mm = units::mToMm(m.cgX(fin.params));
    R.cg_y_mm = units::mToMm(m.cgY(fin.params));
    double vx = 0.0, vy = 0.0;
    for (int j = 0; j < s.nN; ++j) {
      Params q = fin.params;
      q.nuisance[j] += fin.sigma[j];
      vx += std::pow(units::mToMm(m.cgX(q)) - R.cg_x_mm, 2);
      vy += std::pow(units::mToMm(m.cgY(q)) - R.cg_y_mm, 2);
    }
    R.cg_x_sigma_mm = std::sqrt(vx);
    R.cg_y_sigma_mm = std::sqrt(vy);
  }

  // --- 6. RMS before/after, fitted and held-out ----------------------------------------
  {
    const HeldOut hoFinal = accepted.empty() ? hoBase : heldOut(s, halfFit, halfOfRow, accepted, fin.params, SC);
    std::vector<double> eb, ea, nb, na;
    rmsPerChannel(e0raw, s.C, eb, nb);
    const std::vector<double> eqFinal = residualsAt(s, fin.params, all);
    rmsPerChannel(eqFinal, s.C, ea, na);
    for (std::size_t c = 0; c < s.C; ++c) {
      const double k = channelDisplayScale(s.eq[c]);
      R.rms.push_back({s.eq[c], "equation", rmsOf(eb[c], nb[c]) * k, rmsOf(ea[c], na[c]) * k,
                       rmsOf(hoBase.eq_sse[c], hoBase.eq_n[c]) * k, rmsOf(hoFinal.eq_sse[c], hoFinal.eq_n[c]) * k,
                       static_cast<std::size_t>(nb[c])});
    }
    std::vector<double> simBase, simFinal;
    m.simulationError(base.params, simBase);
    m.simulationError(fin.params, simFinal);
    rmsPerChannel(simBase, SC, eb, nb);
    rmsPerChannel(simFinal, SC, ea, na);
    for (std::size_t c = 0; c < SC; ++c) {
      const double k = channelDisplayScale(simCh[c]);
      R.rms.push_back({simCh[c], "simulation", rmsOf(eb[c], nb[c]) * k, rmsOf(ea[c], na[c]) * k,
                       rmsOf(hoBase.sim_sse[c], hoBase.sim_n[c]) * k, rmsOf(hoFinal.sim_sse[c], hoFinal.sim_n[c]) * k,
                       static_cast<std::size_t>(nb[c])});
    }
    // --- 7. localisation of the ballast-only model's residuals ---------------------------
    for (std::size_t c = 0; c < s.C; ++c)
      R.localisation.push_back(localise(S, channelColumn(e0raw, s.C, c), s.eq[c], "equation error"));
    for (std::size_t c = 0; c < SC; ++c)
      R.localisation.push_back(localise(S, channelColumn(simBase, SC, c), simCh[c], "simulation error"));
  }

  // Where each accepted term acts: its own contribution to the model, on the
  // equation channel where it is largest.
  for (auto& mp : found) {
    const std::size_t term = *findTerm(mp.id);
    Params without = fin.params;
    without.terms[term] = 0.0;
    const std::vector<double> rw = residualsAt(s, without, all), rf = residualsAt(s, fin.params, all);
    std::size_t bestC = 0;
    double best = -1.0;
    for (std::size_t c = 0; c < s.C; ++c) {
      double ss = 0.0;
      for (std::size_t i = 0; i < N; ++i) {
        const double d = rw[i * s.C + c] - rf[i * s.C + c];
        if (std::isfinite(d)) ss += d * d * s.weight(c) * s.weight(c);
      }
      if (ss > best) {
        best = ss;
        bestC = c;
      }
    }
    std::vector<double> contrib(N);
    for (std::size_t i = 0; i < N; ++i) contrib[i] = rw[i * s.C + bestC] - rf[i * s.C + bestC];
    mp.where = localise(S, contrib, s.eq[bestC], "term contribution").summary;
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const MissingPhysics& a, const MissingPhysics& b) { return a.heldout_gain > b.heldout_gain; });
  R.missing_physics = found;
  return R;
}

}  // namespace auv::discrepancy
