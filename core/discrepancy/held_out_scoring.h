#pragma once
// Held-out scoring for the model check: the units (dives/legs) split into two
// halves; a model is fitted on one half and its whole-log simulation error
// and equation error are scored on the other, both ways. A term is accepted
// only if it lowers this held-out cost. Internal to the model check.
#include <cstdint>
#include <string>
#include <vector>

#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy::detail {

struct HeldOut {
  std::vector<double> sim_sse, eq_sse;
  std::vector<double> sim_n, eq_n;
  std::vector<double> prior_z2;  // per prior: squared standardised distance of the fit from it (mean of the halves)
  std::vector<Params> fits;      // fitted on half 0 and on half 1
};

class HeldOutScorer {
 public:
  // Units alternate between the halves; a log with a single unit is split at
  // mid-time (and says so in `warnings`). Scores the ballast-only model at
  // `base` as the reference every later cost is relative to.
  HeldOutScorer(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const Params& base,
                std::vector<std::string>& warnings);

  // Ballast state plus `terms`, fitted from `start`.
  HeldOut score(const std::vector<std::size_t>& terms, const Params& start) const;

  // Sum over simulation channels of the held-out mean square relative to the
  // ballast-only model's (floored by channelFloor), plus each prior's misfit
  // relative to the ballast-only model's.
  double cost(const HeldOut& h) const;

  const HeldOut& base() const { return base_; }
  const std::vector<Channel>& channels() const { return simCh_; }
  double reference(std::size_t c) const { return simRef_[c]; }  // mean square the cost divides by

 private:
  const FitSetup& s_;
  std::vector<Channel> simCh_;
  std::vector<int> halfOfRow_;
  std::vector<std::vector<std::uint32_t>> halfFit_;
  HeldOut base_;
  std::vector<double> simRef_;
};

}  // namespace auv::discrepancy::detail
