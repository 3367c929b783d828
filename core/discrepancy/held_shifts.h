#pragma once
// The model check's fit with each held calibration constant (an analysis's
// group, or BG at the profile's) one of its sigmas up. The fit's own sigma
// assumes the held values exact; these refits measure what the held
// constants' uncertainty moves: the ballast state's spread (joint_refit.cpp)
// and whether a term is more than that uncertainty can explain
// (term_acceptance.cpp). Internal to the model check.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy::detail {

// The shifts are systematic, so a subsample of the fit's rows measures them:
// every fit compared with a shifted one runs on the same rows, at most this many.
constexpr std::size_t kSpreadRows = 2000;

std::vector<std::uint32_t> spreadRows(const std::vector<std::uint32_t>& fitRows);

struct HeldShifts {
  Params unshifted;             // fitted on spreadRows (or `at` itself when they are all the rows)
  std::vector<Params> shifted;  // one per held constant, that constant one sigma up
};

// `at`: the full fit with `terms`; empty `shifted` when nothing is held.
HeldShifts heldShifts(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const std::vector<std::size_t>& terms,
                      const Params& at);

}  // namespace auv::discrepancy::detail
