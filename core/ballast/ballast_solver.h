#pragma once
// Which pieces go where. solveBallast is exact: it searches every signed
// piece count per point and size (branch and bound with proved bounds, no
// rounding heuristics) and returns the optimum of the objective in
// docs/decisions/ballast-objective.md, a chain in the thesis's priority order:
//   1. never negative, then net buoyancy in band,
//   2. pitch in band (a pitch inside the band is never traded for roll;
//      out of reach, gains below 0.1 x tolerance count as none),
//   3. roll in band (same rule),
//   4. residual (pitch/tol)^2 + (roll/tol)^2, to 1/100 of a band,
//   5. fewest pieces handled, then fewest removals.
// It never removes more pieces than are installed and keeps every point
// within its capacity. Throws InputError for an ill-formed problem.
// thesisGreedyMapping reproduces the thesis's first-mission method (§5.4.1,
// per-point floor mapping eq. 5.22-5.26) for comparison.
#include "ballast/ballast_problem.h"
#include "ballast/ballast_solution.h"

namespace auv {

BallastSolution solveBallast(const BallastProblem& problem);

BallastSolution thesisGreedyMapping(const BallastProblem& problem);

// The predicted outcome of a given move (delta[point][size]), with band flags
// against problem.spec; notes and warnings are left empty. Used by both
// solvers and by tests that score a hand-made move (e.g. a thesis table row).
BallastSolution evaluateMove(const BallastProblem& problem, const std::vector<std::vector<int>>& delta);

}  // namespace auv
