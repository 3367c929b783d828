#pragma once
// The objective of docs/decisions/ballast-objective.md as a chain of exact
// searches: buoyancy class -> pitch -> roll -> residual, then effort. Each step
// keeps the earlier ones at their optimum (pitch and roll within a small
// slack when their band is out of reach, so that a negligible gain on a
// higher priority cannot cost a large error on a lower one).
#include <cstdint>
#include <vector>

#include "ballast/ballast_problem.h"
#include "ballast/buoyancy_window.h"
#include "ballast/exact_search.h"

namespace auv::ballast {

inline constexpr double kInBandRad = 1e-12;   // "inside the band" up to rounding
inline constexpr double kSlackFraction = 0.1; // slack = 0.1 x the band's tolerance
// Per step. HUGIN-size problems need a few hundred nodes; only many points
// with fine kits come near this, and then the answer is flagged unproved.
inline constexpr long kNodeLimit = 2'000'000;

struct Optimum {
  Candidate best;
  TotalWindow window;            // buoyancy class and the totals in it
  double pitch_best = 0;         // least pitch violation (rad) in that class
  double pitch_allowed = 0;      // what later steps may use
  double roll_best = 0, roll_allowed = 0;
  double residual_best = 0;
  SearchStats stats;             // summed over the steps
};

TrimModel trimModel(const BallastProblem& problem);
std::vector<std::int64_t> sizesInQuanta(const std::vector<double>& sizes_kg);
// Options per point for the given sizes; sizes beyond the problem's kit are
// extra sizes with nothing installed.
std::vector<PointOptions> allPointOptions(const BallastProblem& problem, const std::vector<std::int64_t>& sizes_q);

Optimum lexicographicOptimum(const TrimModel& model, const TrimTargets& targets,
                             const std::vector<PointOptions>& points);

double allowance(double best, double tolerance);

}  // namespace auv::ballast
