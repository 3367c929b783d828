#include "discrepancy/held_out_scoring.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "discrepancy/residual_statistics.h"

namespace auv::discrepancy::detail {

HeldOutScorer::HeldOutScorer(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const Params& base,
                             std::vector<std::string>& warnings)
    : s_(s), simCh_(s.m.simulationChannels()) {
  const SampleTable& S = s.m.samples();
  const std::size_t N = S.size();
  halfOfRow_.resize(N);
  if (S.unitCount() >= 2) {
    for (std::size_t i = 0; i < N; ++i) halfOfRow_[i] = S.unit[i] % 2;
  } else {
    const double tm = 0.5 * (S.t.front() + S.t.back());
    for (std::size_t i = 0; i < N; ++i) halfOfRow_[i] = S.t[i] < tm ? 0 : 1;
    warnings.push_back("the log has a single dive/leg: held-out checks use its two halves in time");
  }
  halfFit_.resize(2);
  for (std::uint32_t i : fitRows) halfFit_[static_cast<std::size_t>(halfOfRow_[i])].push_back(i);

  baseParams_ = base;
  base_ = score({}, base);
  simRef_ = meanSquares(base_, simCh_);
}

std::vector<double> HeldOutScorer::meanSquares(const HeldOut& h, const std::vector<Channel>& ch) {
  std::vector<double> r(ch.size());
  for (std::size_t c = 0; c < ch.size(); ++c) {
    const double f = channelFloor(ch[c]);
    r[c] = std::max(h.sim_n[c] > 0 ? h.sim_sse[c] / h.sim_n[c] : 0.0, f * f);
  }
  return r;
}

const std::vector<double>& HeldOutScorer::references(bool short_horizons) const {
  if (!short_horizons) return simRef_;
  if (simRefShort_.empty()) simRefShort_ = meanSquares(score({}, baseParams_, true), simCh_);
  return simRefShort_;
}

HeldOut HeldOutScorer::score(const std::vector<std::size_t>& terms, const Params& start, bool short_horizons) const {
  const FitSetup& s = s_;
  const std::size_t simC = simCh_.size();
  HeldOut h;
  h.sim_sse.assign(simC, 0.0);
  h.sim_n.assign(simC, 0.0);
  h.eq_sse.assign(s.C, 0.0);
  h.eq_n.assign(s.C, 0.0);
  h.prior_z2.assign(s.priors.size(), 0.0);
  const std::size_t N = halfOfRow_.size();
  std::vector<std::uint32_t> all(N);
  std::iota(all.begin(), all.end(), 0u);
  for (int half = 0; half < 2; ++half) {
    const Fit f = fit(s, halfFit_[static_cast<std::size_t>(half)], terms, start);
    h.fits.push_back(f.params);
    // A prior is an independent measurement (e.g. the roll test's CG y): the
    // model fitted to the flight data must reproduce it, like any held-out data.
    for (std::size_t k = 0; k < s.priors.size(); ++k) {
      const double z = (f.params.nuisance[s.priors[k].index] - s.priors[k].mean) / s.priors[k].sigma;
      h.prior_z2[k] += 0.5 * z * z;
    }
    std::vector<double> sim;
    if (short_horizons)
      s.m.shortHorizonSimulationError(f.params, sim);
    else
      s.m.simulationError(f.params, sim);
    const std::vector<double> eq = residualsAt(s, f.params, all);
    for (std::size_t i = 0; i < N; ++i) {
      if (halfOfRow_[i] == half) continue;
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

double HeldOutScorer::cost(const HeldOut& h, bool short_horizons) const {
  const std::vector<double>& ref = references(short_horizons);
  double c = 0.0;
  for (std::size_t k = 0; k < simCh_.size(); ++k)
    if (h.sim_n[k] > 0) c += h.sim_sse[k] / h.sim_n[k] / ref[k];
  // Only independent measurements are held-out data; a calibration
  // constant's soft prior is not (a term must not win by pulling it back).
  for (std::size_t k = 0; k < h.prior_z2.size(); ++k)
    if (s_.priors[k].measured) c += std::max(1.0, h.prior_z2[k]) / std::max(1.0, base_.prior_z2[k]);
  return c;
}

}  // namespace auv::discrepancy::detail
