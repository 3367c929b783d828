#include "ballast/extra_piece.h"

#include <algorithm>

#include "ballast/mass_quanta.h"

namespace auv::ballast {
namespace {

// A suggestion is advice, not the answer: it gets a smaller budget.
constexpr long kSuggestionNodeLimit = 100'000;

// Each point as the interval of masses it could take with arbitrarily fine
// pieces: only the ends matter to the relaxation.
std::vector<PointOptions> continuousPoints(const BallastProblem& pr) {
  std::vector<PointOptions> out;
  for (std::size_t p = 0; p < pr.points.size(); ++p) {
    const std::int64_t inst = toQuanta(installedMassKg(pr, p));
    const std::int64_t cap = toQuanta(pr.points[p].capacity_kg);
    PointOptions o;
    o.position_m = pr.points[p].position_m;
    o.mass_q = {-inst, std::max(-inst, cap - inst)};
    if (o.mass_q[1] == o.mass_q[0]) o.mass_q.pop_back();
    for (std::int64_t m : o.mass_q) {
      o.mass_kg.push_back(toKg(m));
      o.effort.push_back(0);
      o.removals.push_back(0);
    }
    out.push_back(std::move(o));
  }
  return out;
}

bool provedOutOfReach(const BallastProblem& pr, const TrimModel& model, const TrimTargets& targets,
                      const Optimum& current, Band band) {
  const std::vector<PointOptions> points = continuousPoints(pr);
  const double net_now = model.displaced_kg - model.mass_kg;
  if (band == Band::Buoyancy) {
    std::int64_t lo = 0, hi = 0;
    for (const PointOptions& p : points) {
      lo += p.mass_q.front();
      hi += p.mass_q.back();
    }
    // Any total inside [net_now - net_hi, net_now - net_lo] would do.
    return toKg(hi) < net_now - targets.net_hi_kg - 1e-6 || toKg(lo) > net_now - targets.net_lo_kg + 1e-6;
  }
  const TotalWindow w = continuousWindow(net_now, targets.net_lo_kg, targets.net_hi_kg, current.window.best);
  ExactSearch search(model, targets, points);
  PhaseSpec ph;
  ph.total_lo_q = w.lo_q;
  ph.total_hi_q = w.hi_q;
  const auto b = search.relaxedBound(ph);
  return band == Band::Pitch ? b.pitch > kInBandRad : b.roll > kInBandRad;
}

}  // namespace

ExtraPieceAnswer extraPieceReaching(const BallastProblem& pr, const TrimModel& model, const TrimTargets& targets,
                                    const Optimum& current, Band band) {
  static const double kCandidates[] = {0.6, 0.5, 0.4, 0.3, 0.2, 0.1};
  ExtraPieceAnswer answer;
  if (provedOutOfReach(pr, model, targets, current, band)) {
    answer.out_of_reach = true;
    return answer;
  }
  const double smallest = pr.piece_sizes_kg.empty() ? 1e9 : pr.piece_sizes_kg.front();
  const double net_now = model.displaced_kg - model.mass_kg;
  for (double c : kCandidates) {
    if (c >= smallest - 1e-9) continue;
    answer.tried_kg.push_back(c);
    std::vector<std::int64_t> sizes_q = sizesInQuanta(pr.piece_sizes_kg);
    sizes_q.push_back(toQuanta(c));
    const std::vector<PointOptions> options = allPointOptions(pr, sizes_q);
    const std::vector<std::int64_t> totals = reachableTotals(options);
    bool reached = false;
    if (band == Band::Buoyancy) {
      const TotalWindow w = bestWindow(totals, net_now, targets.net_lo_kg, targets.net_hi_kg);
      reached = w.best.negative_kg <= 1e-6 && w.best.band_violation_kg <= 1e-6;
    } else {
      const TotalWindow w =
          windowNoWorseThan(totals, net_now, targets.net_lo_kg, targets.net_hi_kg, current.window.best);
      if (w.lo_q > w.hi_q) continue;
      // A feasibility question: the band is a hard limit, so the search only
      // walks nodes whose relaxation can still meet it and stops at the first hit.
      ExactSearch search(model, targets, options);
      PhaseSpec ph;
      ph.total_lo_q = w.lo_q;
      ph.total_hi_q = w.hi_q;
      ph.node_limit = kSuggestionNodeLimit;
      if (band == Band::Pitch) {
        ph.goal = Goal::Pitch;
        ph.pitch_max = kInBandRad;
      } else {
        ph.goal = Goal::Roll;
        ph.pitch_max = current.pitch_allowed;
        ph.roll_max = kInBandRad;
      }
      reached = search.run(ph).has_value();
      answer.undecided = answer.undecided || (!reached && search.stats().limited);
    }
    if (reached) {
      answer.size_kg = c;
      return answer;
    }
  }
  return answer;
}

}  // namespace auv::ballast
