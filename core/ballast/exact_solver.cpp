#include <algorithm>
#include <cmath>
#include <string>

#include "ballast/ballast_solver.h"
#include "ballast/extra_piece.h"
#include "ballast/lexicographic_optimum.h"
#include "ballast/ballast_messages.h"
#include "ballast/solution_text.h"
#include "common/units.h"

namespace auv {
namespace {

using namespace ballast;

std::string suffix(const ExtraPieceAnswer& a);

// What an extra piece would do, as the two message arguments (kind, size(s)).
std::pair<std::string, std::string> extraArgs(const ExtraPieceAnswer& a) {
  if (a.out_of_reach) return {"out_of_reach", ""};
  if (a.size_kg) return {"piece", sizeText(*a.size_kg)};
  if (a.tried_kg.empty()) return {"", ""};
  std::string sizes;
  for (double s : a.tried_kg) sizes += (sizes.empty() ? "" : ", ") + sizeText(s);
  return {a.undecided ? "none_tried_undecided" : "none_tried", sizes};
}

// A band the kit cannot reach (ballast_messages.h): English as before, with its arguments.
Message bandUnreachable(const std::string& english, const char* band, const std::string& lo, const std::string& hi,
                        const std::string& best, const ExtraPieceAnswer& a, bool pitch_ok) {
  const auto [kind, extra] = extraArgs(a);
  return Message(msg::kBandUnreachableId, english + suffix(a), {band, lo, hi, best, kind, extra, pitch_ok ? "pitch_ok" : ""});
}

std::string suffix(const ExtraPieceAnswer& a) {
  if (a.out_of_reach) {
    return "; out of reach whatever the piece sizes: the points' capacities, the installed pieces and the "
           "higher priorities limit it";
  }
  if (a.size_kg) return "; a " + sizeText(*a.size_kg) + " piece would reach it";
  if (a.tried_kg.empty()) return "";
  std::string sizes;
  for (double s : a.tried_kg) sizes += (sizes.empty() ? "" : ", ") + sizeText(s);
  return "; no single extra piece size tried (" + sizes + ") would reach it" +
         (a.undecided ? " (some were not searched to the end)" : "");
}

void explain(const BallastProblem& pr, const TrimModel& model, const TrimTargets& targets, const Optimum& opt,
             BallastSolution& sol) {
  const TrimSpec& spec = pr.spec;
  const double lo = std::max(0.0, spec.net_buoyancy_min_kg);
  int handled = 0;
  for (std::size_t p = 0; p < pr.points.size(); ++p) {
    const double before = installedMassKg(pr, p);
    sol.notes.push_back(pointNote(pr.points[p], pr.piece_sizes_kg, sol.delta[p].data(), before, before + sol.add_kg[p]));
    for (int d : sol.delta[p]) handled += std::abs(d);
  }
  sol.notes.push_back(Message(msg::kPriorities, {kgText(lo), kgText(spec.net_buoyancy_max_kg),
                                                 degText(spec.pitch_tolerance_deg), degText(spec.roll_tolerance_deg),
                                                 std::to_string(handled)}));
  sol.notes.push_back(
      Message(msg::kAfterMove, {signedKgText(sol.net_buoyancy_kg), signedDegText(sol.pitch_deg), signedDegText(sol.roll_deg)}));

  if (pr.policy == BallastPolicy::HalfWay) {
    sol.notes.push_back(Message(msg::kHalfWay, {kgText(targets.net_lo_kg), kgText(targets.net_hi_kg),
                                                signedDegText(units::radToDeg(targets.pitch_centre)),
                                                signedDegText(units::radToDeg(targets.roll_centre))}));
  } else {
    if (opt.window.best.negative_kg > 1e-6) {
      // said below, for both policies
    } else if (opt.window.best.band_violation_kg > 1e-6) {
      sol.warnings.push_back(bandUnreachable("net buoyancy band " + kgText(lo) + " to " + kgText(spec.net_buoyancy_max_kg) +
                                                 " not reachable with this kit; best " + signedKgText(sol.net_buoyancy_kg),
                                             "net buoyancy", kgText(lo), kgText(spec.net_buoyancy_max_kg),
                                             signedKgText(sol.net_buoyancy_kg),
                                             extraPieceReaching(pr, model, targets, opt, Band::Buoyancy), false));
    }
    // Warn on the exact attitude; the solver ranks pitch by pitch_x, which is
    // never smaller, so a band it missed may still be met once roll is counted.
    if (opt.pitch_best > kInBandRad && !sol.pitch_in_band) {
      sol.warnings.push_back(bandUnreachable("pitch band \u00b1" + degText(spec.pitch_tolerance_deg) +
                                                 " not reachable with this kit; best " + signedDegText(sol.pitch_deg),
                                             "pitch", degText(spec.pitch_tolerance_deg), "", signedDegText(sol.pitch_deg),
                                             extraPieceReaching(pr, model, targets, opt, Band::Pitch), false));
    }
    if (opt.roll_best > kInBandRad && !sol.roll_in_band) {
      const bool pitch_ok = opt.pitch_best <= kInBandRad;
      sol.warnings.push_back(bandUnreachable("roll band \u00b1" + degText(spec.roll_tolerance_deg) +
                                                 " not reachable with this kit" +
                                                 (pitch_ok ? " while pitch stays in band" : "") + "; best " +
                                                 signedDegText(sol.roll_deg),
                                             "roll", degText(spec.roll_tolerance_deg), "", signedDegText(sol.roll_deg),
                                             extraPieceReaching(pr, model, targets, opt, Band::Roll), pitch_ok));
    }
  }
  if (opt.window.best.negative_kg > 1e-6) {
    sol.warnings.push_back(Message(msg::kStaysHeavy, {kgText(opt.window.best.negative_kg)}));
  }
  if (opt.stats.limited) {
    sol.warnings.push_back(Message(msg::kNodeLimit));
  }
  if (!opt.best.outcome.stable) {
    sol.warnings.push_back(Message(msg::kCapsize));
  }
}

}  // namespace

BallastSolution solveBallast(const BallastProblem& pr) {
  validateBallastProblem(pr);
  const TrimModel model = trimModel(pr);
  const std::vector<PointOptions> options = allPointOptions(pr, sizesInQuanta(pr.piece_sizes_kg));
  TrimTargets targets = exactTargets(pr.spec);
  if (pr.policy == BallastPolicy::HalfWay) {
    const TrimOutcome now = model.outcome(0.0, Eigen::Vector3d::Zero());
    targets = halfWayTargets(pr.spec, now.net_kg, now.pitch_x_rad, now.roll_rad);
  }
  const Optimum opt = lexicographicOptimum(model, targets, options);

  std::vector<std::vector<int>> delta;
  for (std::size_t p = 0; p < options.size(); ++p) {
    const int* d = options[p].deltaOf(static_cast<std::size_t>(opt.best.option[p]));
    delta.emplace_back(d, d + options[p].sizes);
  }
  BallastSolution sol = evaluateMove(pr, delta);
  explain(pr, model, targets, opt, sol);
  return sol;
}

}  // namespace auv
