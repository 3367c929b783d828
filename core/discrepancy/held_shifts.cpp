#include "discrepancy/held_shifts.h"

#include <algorithm>

namespace auv::discrepancy::detail {

std::vector<std::uint32_t> spreadRows(const std::vector<std::uint32_t>& fitRows) {
  std::vector<std::uint32_t> rows;
  const std::size_t stride = std::max<std::size_t>(1, (fitRows.size() + kSpreadRows - 1) / kSpreadRows);
  for (std::size_t i = 0; i < fitRows.size(); i += stride) rows.push_back(fitRows[i]);
  return rows;
}

HeldShifts heldShifts(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const std::vector<std::size_t>& terms,
                      const Params& at) {
  HeldShifts out;
  out.unshifted = at;
  std::vector<CalibrationConstant> held;
  for (const CalibrationConstant& k : s.m.calibrationConstants()) {
    const auto j = static_cast<Eigen::Index>(k.index);
    if (k.held_sigma > 0.0 && !(s.nHi[j] > s.nLo[j])) held.push_back(k);  // held by its bounds
  }
  if (held.empty()) return out;
  const std::vector<std::uint32_t> rows = spreadRows(fitRows);
  if (rows.size() != fitRows.size()) out.unshifted = fit(s, rows, terms, at).params;
  for (const CalibrationConstant& k : held) {
    const auto j = static_cast<Eigen::Index>(k.index);
    FitSetup moved = s;
    const double v = out.unshifted.nuisance[j] + k.held_sigma / k.display_scale;
    moved.nLo[j] = moved.nHi[j] = v;
    for (NuisancePrior& q : moved.priors)
      if (q.index == k.index) q.mean = v;
    Params start = out.unshifted;
    start.nuisance[j] = v;
    out.shifted.push_back(fit(moved, rows, terms, start).params);
  }
  return out;
}

}  // namespace auv::discrepancy::detail
