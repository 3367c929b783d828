#pragma once
// When a band is out of reach with the kit, would one more piece size reach
// it? Tries a few sizes finer than the kit, coarsest first, and names the
// coarsest that works: the operator wants the fewest, largest pieces.
#include <optional>
#include <vector>

#include "ballast/ballast_problem.h"
#include "ballast/lexicographic_optimum.h"

namespace auv::ballast {

enum class Band { Buoyancy, Pitch, Roll };

struct ExtraPieceAnswer {
  bool out_of_reach = false;        // no masses at all within capacities reach it (proved by the relaxation)
  std::optional<double> size_kg;    // coarsest candidate that reaches the band
  std::vector<double> tried_kg;     // candidates looked at, coarsest first
  bool undecided = false;           // some candidate hit the search budget without an answer
};

// Candidates: 0.6, 0.5, 0.4, 0.3, 0.2, 0.1 kg, those smaller than the kit's
// smallest piece. Reaching means: the band is met and no higher priority is
// worse than in `current` (buoyancy class, and for roll the pitch allowance).
ExtraPieceAnswer extraPieceReaching(const BallastProblem& problem, const TrimModel& model,
                                    const TrimTargets& targets, const Optimum& current, Band band);

}  // namespace auv::ballast
