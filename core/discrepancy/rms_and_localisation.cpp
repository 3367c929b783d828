#include "discrepancy/rms_and_localisation.h"

#include <cmath>

#include "discrepancy/localisation.h"
#include "discrepancy/residual_statistics.h"

namespace auv::discrepancy::detail {

void reportRmsAndLocalisation(const FitSetup& s, const HeldOutScorer& scorer, const std::vector<std::size_t>& accepted,
                              const Params& base, const Params& fin, const std::vector<double>& baseResiduals,
                              const std::vector<std::uint32_t>& all, ModelCheckResult& R) {
  const CheckModel& m = s.m;
  const SampleTable& S = m.samples();
  const std::vector<Channel>& simCh = scorer.channels();
  const std::size_t SC = simCh.size();
  const HeldOut& hoBase = scorer.base();
  const HeldOut hoFinal = accepted.empty() ? hoBase : scorer.score(accepted, fin);
  std::vector<double> eb, ea, nb, na;
  rmsPerChannel(baseResiduals, s.C, eb, nb);
  const std::vector<double> eqFinal = residualsAt(s, fin, all);
  rmsPerChannel(eqFinal, s.C, ea, na);
  for (std::size_t c = 0; c < s.C; ++c) {
    const double k = channelDisplayScale(s.eq[c]);
    R.rms.push_back({s.eq[c], "equation", rmsOf(eb[c], nb[c]) * k, rmsOf(ea[c], na[c]) * k,
                     rmsOf(hoBase.eq_sse[c], hoBase.eq_n[c]) * k, rmsOf(hoFinal.eq_sse[c], hoFinal.eq_n[c]) * k,
                     static_cast<std::size_t>(nb[c])});
  }
  std::vector<double> simBase, simFinal;
  m.simulationError(base, simBase);
  m.simulationError(fin, simFinal);
  rmsPerChannel(simBase, SC, eb, nb);
  rmsPerChannel(simFinal, SC, ea, na);
  for (std::size_t c = 0; c < SC; ++c) {
    const double k = channelDisplayScale(simCh[c]);
    R.rms.push_back({simCh[c], "simulation", rmsOf(eb[c], nb[c]) * k, rmsOf(ea[c], na[c]) * k,
                     rmsOf(hoBase.sim_sse[c], hoBase.sim_n[c]) * k, rmsOf(hoFinal.sim_sse[c], hoFinal.sim_n[c]) * k,
                     static_cast<std::size_t>(nb[c])});
  }
  for (std::size_t c = 0; c < s.C; ++c)
    R.localisation.push_back(localise(S, channelColumn(baseResiduals, s.C, c), s.eq[c], "equation error"));
  for (std::size_t c = 0; c < SC; ++c)
    R.localisation.push_back(localise(S, channelColumn(simBase, SC, c), simCh[c], "simulation error"));
}

void locateAcceptedTerms(const FitSetup& s, const Params& fin, const std::vector<std::uint32_t>& all,
                         std::vector<MissingPhysics>& found) {
  for (auto& mp : found) {
    Params without = fin;
    without.terms[*findTerm(mp.id)] = 0.0;
    mp.where = locateContribution(s, without, fin, all);
  }
}

Message locateContribution(const FitSetup& s, const Params& without, const Params& with,
                           const std::vector<std::uint32_t>& all) {
  const std::size_t N = all.size();
  const std::vector<double> rw = residualsAt(s, without, all), rf = residualsAt(s, with, all);
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
  return localise(s.m.samples(), contrib, s.eq[bestC], "term contribution").summary;
}

}  // namespace auv::discrepancy::detail
