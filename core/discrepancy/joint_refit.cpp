#include "discrepancy/joint_refit.h"

#include <algorithm>
#include <cmath>

#include "common/units.h"

namespace auv::discrepancy::detail {

Fit jointRefit(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const std::vector<std::size_t>& accepted,
               const Params& base, std::vector<MissingPhysics>& found, ModelCheckResult& R) {
  const CheckModel& m = s.m;
  const auto& lib = termLibrary();
  Params st = base;
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
  return fin;
}

}  // namespace auv::discrepancy::detail
