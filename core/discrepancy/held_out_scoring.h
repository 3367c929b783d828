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

  // Ballast state plus `terms`, fitted from `start`; simulated over the whole
  // log, or in short horizons (CheckModel::shortHorizonSimulationError).
  HeldOut score(const std::vector<std::size_t>& terms, const Params& start, bool short_horizons = false) const;

  // Sum over simulation channels of the held-out mean square relative to the
  // ballast-only model's on the same horizons (floored by channelFloor), plus
  // each prior's misfit relative to the ballast-only model's.
  double cost(const HeldOut& h, bool short_horizons = false) const;

  const HeldOut& base() const { return base_; }
  const std::vector<Channel>& channels() const { return simCh_; }
  // Mean square the cost divides by.
  double reference(std::size_t c, bool short_horizons = false) const { return references(short_horizons)[c]; }

 private:
  const FitSetup& s_;
  std::vector<Channel> simCh_;
  std::vector<int> halfOfRow_;
  std::vector<std::vector<std::uint32_t>> halfFit_;
  const std::vector<double>& references(bool short_horizons) const;
  static std::vector<double> meanSquares(const HeldOut& h, const std::vector<Channel>& channels);

  Params baseParams_;
  HeldOut base_;
  std::vector<double> simRef_;
  mutable std::vector<double> simRefShort_;  // scored when a transient term first needs it
};

}  // namespace auv::discrepancy::detail
