#pragma once
// Steps 6 and 7 of the model check: RMS per channel before (ballast state
// only) and after (with the accepted terms), on the fitted and on held-out
// data; where the ballast-only model's residuals concentrate; and where each
// accepted term acts. Internal to the model check.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "discrepancy/held_out_scoring.h"
#include "discrepancy/model_check.h"

namespace auv::discrepancy::detail {

// `baseResiduals`: equation error of `base` at `all` rows. Appends to R.rms
// (equation channels, then simulation channels) and R.localisation.
void reportRmsAndLocalisation(const FitSetup& s, const HeldOutScorer& scorer, const std::vector<std::size_t>& accepted,
                              const Params& base, const Params& fin, const std::vector<double>& baseResiduals,
                              const std::vector<std::uint32_t>& all, ModelCheckResult& R);

// Sets `where` of each entry: the localisation of the term's own contribution
// to the model, on the equation channel where it is largest (weighted).
void locateAcceptedTerms(const FitSetup& s, const Params& fin, const std::vector<std::uint32_t>& all,
                         std::vector<MissingPhysics>& found);

// Where the model at `with` differs from it at `without`: the localisation of
// the difference on the equation channel where it is largest (weighted).
Message locateContribution(const FitSetup& s, const Params& without, const Params& with,
                           const std::vector<std::uint32_t>& all);

}  // namespace auv::discrepancy::detail
