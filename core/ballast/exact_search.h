#pragma once
// Branch and bound over the per-point options. One call minimises one goal
// (pitch violation, roll violation, residual or effort) subject to limits on
// the others and to a window of total added mass; solveBallast chains calls
// to get the lexicographic optimum (docs/decisions/ballast-objective.md).
//
// Bounds: with some points fixed, the rest can add any masses within their
// [min, max] whose total keeps the window. Over that polytope each component
// of d = W r_G - B r_B has an exact range (a fractional knapsack per axis),
// and pitch_x = atan2(-d_x, d_z), roll = atan2(d_y, d_z) are monotone in the
// components where d_z > 0, so their ranges over the box are at its corners.
// The bound is therefore a true lower bound and nothing better than the
// incumbent is cut.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "ballast/point_options.h"
#include "ballast/trim_model.h"
#include "ballast/trim_targets.h"

namespace auv::ballast {

// ResidualThenEffort: least residual step (residualStep); within the same
// step, fewest pieces handled, then fewest removals.
enum class Goal { Pitch, Roll, ResidualThenEffort };

// The residual's resolution: sqrt(residual) is the attitude error in units
// of the bands; errors within the same 1/100 of a band are equal, and the
// technician's effort decides between them.
inline constexpr double kResidualResolution = 0.01;
inline double residualStep(double residual) { return std::floor(std::sqrt(residual) / kResidualResolution); }

struct PhaseSpec {
  std::int64_t total_lo_q = 0, total_hi_q = 0;
  double pitch_max = std::numeric_limits<double>::infinity();  // rad of violation allowed
  double roll_max = std::numeric_limits<double>::infinity();
  double residual_max = std::numeric_limits<double>::infinity();
  Goal goal = Goal::Pitch;
  long node_limit = 0;  // stop after this many inner nodes (0 = never); see SearchStats::limited
};

struct Candidate {
  std::vector<int> option;  // chosen option index per point (caller's point order)
  TrimOutcome outcome;
  TrimScores scores;
  int effort = 0, removals = 0;
};

struct SearchStats {
  long nodes = 0, leaves = 0;
  bool limited = false;  // the node limit stopped the search: the result is the best found, not proved
};

class ExactSearch {
 public:
  ExactSearch(const TrimModel& model, const TrimTargets& targets, const std::vector<PointOptions>& points);

  // Best candidate for the phase, or nullopt if nothing meets the limits.
  // `start`, if given and feasible for the phase, seeds the incumbent.
  // The search stops by itself once the incumbent reaches the goal's floor
  // (a violation of 0), so feasibility questions cost little when the answer is yes.
  std::optional<Candidate> run(const PhaseSpec& phase, const Candidate* start = nullptr);

  Candidate evaluate(const std::vector<int>& option) const;

  // Lower bounds at the root: what no choice of masses within the points'
  // ranges and the phase's window can beat, whatever the piece sizes.
  struct Bound {
    double pitch, roll, residual, heuristic;
  };
  Bound relaxedBound(const PhaseSpec& phase);
  const SearchStats& stats() const { return stats_; }

 private:
  struct Pt {
    Eigen::Vector3d r;
    const PointOptions* opt;
    double lo_kg, hi_kg;
    std::int64_t lo_q, hi_q;
    int min_effort, min_removals;
    std::size_t original;
  };
  struct Value {
    double primary = 0, secondary = 0;  // secondary: effort key, ResidualThenEffort only
  };
  struct Child {
    Value key;
    double heuristic;
    std::size_t index;
  };

  Bound bound(std::size_t level, std::int64_t fixed_q, const Eigen::Vector3d& d) const;
  Bound boundFromBox(const double lo[3], const double hi[3]) const;
  Value goalValue(const TrimScores& s, int effort, int removals) const;
  Value goalBound(const Bound& b, int effort, int removals, std::size_t level) const;
  bool better(const Value& a, const Value& b) const;       // a strictly better than b
  bool mayImprove(const Value& bound) const;              // vs the incumbent
  bool admissible(const Bound& b) const;
  void dfs(std::size_t level, std::int64_t fixed_q, const Eigen::Vector3d& d, int effort, int removals);
  void leaves(std::int64_t fixed_q, const Eigen::Vector3d& d, int effort, int removals);
  std::pair<double, double> lpRange(std::size_t level, int axis, double a_kg, double b_kg) const;

  TrimModel model_;
  TrimTargets targets_;
  std::vector<Pt> pts_;                            // search order (fore to aft)
  std::vector<std::int64_t> rest_lo_q_, rest_hi_q_;  // sums over levels >= k
  std::vector<int> rest_effort_, rest_removals_;
  std::vector<std::array<std::vector<std::size_t>, 3>> order_;  // per level, per axis: ascending coefficient
  std::vector<double> rest_lo_kg_;
  std::vector<std::array<double, 3>> rest_val0_;  // sum over levels >= k of lo_kg * r
  std::vector<std::vector<Child>> buffers_;

  PhaseSpec phase_;
  bool have_best_ = false;
  Value best_value_;
  std::vector<int> path_, best_path_;
  Candidate best_;
  SearchStats stats_;
};

}  // namespace auv::ballast
