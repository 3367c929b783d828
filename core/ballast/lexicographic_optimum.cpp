#include "ballast/lexicographic_optimum.h"

#include <algorithm>
#include <stdexcept>

#include "ballast/mass_quanta.h"

namespace auv::ballast {
namespace {

void add(SearchStats& into, const SearchStats& s) {
  into.nodes += s.nodes;
  into.leaves += s.leaves;
  into.limited = into.limited || s.limited;
}

}  // namespace

TrimModel trimModel(const BallastProblem& pr) {
  TrimModel m;
  m.mass_kg = pr.vehicle.mass_kg;
  m.displaced_kg = pr.displaced_mass_kg;
  // From mass and CG rather than moment_kgm: both are always set together by
  // massProperties/add, but a hand-filled struct may only carry mass and CG.
  m.d0 = pr.vehicle.mass_kg * pr.vehicle.cg_m - pr.displaced_mass_kg * pr.cb_m;
  return m;
}

std::vector<std::int64_t> sizesInQuanta(const std::vector<double>& sizes_kg) {
  std::vector<std::int64_t> q;
  for (double s : sizes_kg) q.push_back(toQuanta(s));
  return q;
}

std::vector<PointOptions> allPointOptions(const BallastProblem& pr, const std::vector<std::int64_t>& sizes_q) {
  std::vector<PointOptions> out;
  for (std::size_t p = 0; p < pr.points.size(); ++p) {
    std::vector<int> inst(sizes_q.size(), 0);
    for (std::size_t s = 0; s < pr.piece_sizes_kg.size() && s < sizes_q.size(); ++s) {
      inst[s] = installedCount(pr, p, s);
    }
    out.push_back(pointOptions(pr.points[p].position_m, sizes_q, inst, toQuanta(pr.points[p].capacity_kg)));
  }
  return out;
}

double allowance(double best, double tolerance) {
  return best <= kInBandRad ? kInBandRad : best + kSlackFraction * tolerance + kInBandRad;
}

Optimum lexicographicOptimum(const TrimModel& model, const TrimTargets& targets,
                             const std::vector<PointOptions>& points) {
  Optimum o;
  const double net_now = model.displaced_kg - model.mass_kg;
  o.window = bestWindow(reachableTotals(points), net_now, targets.net_lo_kg, targets.net_hi_kg);
  ExactSearch search(model, targets, points);
  PhaseSpec ph;
  ph.total_lo_q = o.window.lo_q;
  ph.total_hi_q = o.window.hi_q;
  ph.node_limit = kNodeLimit;

  ph.goal = Goal::Pitch;
  auto step = search.run(ph);
  add(o.stats, search.stats());
  // The window holds reachable totals only, so every step has a candidate.
  if (!step) throw std::logic_error("ballast: no candidate in the buoyancy window");
  o.pitch_best = step->scores.pitch_violation;
  o.pitch_allowed = ph.pitch_max = allowance(o.pitch_best, targets.pitch_scale);

  ph.goal = Goal::Roll;
  step = search.run(ph, &*step);
  add(o.stats, search.stats());
  if (!step) throw std::logic_error("ballast: roll step lost its seed");
  o.roll_best = step->scores.roll_violation;
  o.roll_allowed = ph.roll_max = allowance(o.roll_best, targets.roll_scale);

  ph.goal = Goal::ResidualThenEffort;
  step = search.run(ph, &*step);
  add(o.stats, search.stats());
  if (!step) throw std::logic_error("ballast: residual step lost its seed");
  o.residual_best = step->scores.residual;
  o.best = *step;
  return o;
}

}  // namespace auv::ballast
