#include "discrepancy/noise_twin_test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace auv::discrepancy::detail {

namespace {

template <class Result>
auto candidate(Result& r, const std::string& id) -> decltype(&r.candidates.front()) {
  for (auto& c : r.candidates)
    if (c.id == id) return &c;
  return nullptr;
}

}  // namespace

void testAgainstNoiseTwin(const CheckModel& m, const Params& base,
                          const ModelCheckOptions& o, TermAcceptance& acc, ModelCheckResult& R) {
  const std::unique_ptr<CheckModel> twin = m.noiseTwin(base, o.seed * 7919 + 17);
  if (!twin) return;
  ModelCheckOptions to = o;
  to.noise_twin = false;
  to.selection_only = true;
  to.bootstrap_replicates = 2;  // the inclusion is not used
  to.only_terms.clear();
  for (const MissingPhysics& mp : acc.found) to.only_terms.push_back(mp.id);
  const ModelCheckResult T = runModelCheck(*twin, to);
  for (std::size_t i = acc.found.size(); i-- > 0;) {
    const std::string& id = acc.found[i].id;
    CandidateReport* real = candidate(R, id);
    const CandidateReport* tw = candidate(T, id);
    if (real == nullptr || tw == nullptr) continue;
    const double z = (real->value - tw->value) / std::max(std::hypot(real->sigma, tw->sigma), 1e-300);
    real->twin_value = tw->value;
    real->twin_sigma = tw->sigma;
    if (std::abs(z) >= o.min_twin_z && std::signbit(real->value - tw->value) == std::signbit(real->value)) continue;
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "what the closed loop makes of this log's sensor noise: the same check gives %.3g +- %.2g on the log "
                  "flown again by the fitted vehicle without it, with the log's noise (log %.3g +- %.2g)",
                  tw->value, tw->sigma, real->value, real->sigma);
    real->status = buf;
    const auto term = findTerm(id);
    if (term) {
      acc.accepted.erase(std::remove(acc.accepted.begin(), acc.accepted.end(), *term), acc.accepted.end());
      R.accepted[*term] = 0.0;
    }
    acc.found.erase(acc.found.begin() + static_cast<long>(i));
  }
}

}  // namespace auv::discrepancy::detail
