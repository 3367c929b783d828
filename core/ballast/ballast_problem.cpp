#include "ballast/ballast_problem.h"

#include <cmath>
#include <string>

#include "common/input_error.h"

namespace auv {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

}  // namespace

int installedCount(const BallastProblem& problem, std::size_t point, std::size_t size) {
  if (point >= problem.installed.size()) return 0;
  const auto& row = problem.installed[point];
  return size < row.size() ? row[size] : 0;
}

double installedMassKg(const BallastProblem& problem, std::size_t point) {
  double m = 0.0;
  for (std::size_t s = 0; s < problem.piece_sizes_kg.size(); ++s) {
    m += installedCount(problem, point, s) * problem.piece_sizes_kg[s];
  }
  return m;
}

void validateBallastProblem(const BallastProblem& pr) {
  if (!(pr.vehicle.mass_kg > 0.0) || !std::isfinite(pr.vehicle.mass_kg) || !finite(pr.vehicle.cg_m)) {
    throw InputError("vehicle", "mass must be positive and the CG finite", "weigh the vehicle first");
  }
  if (!(pr.displaced_mass_kg > 0.0) || !std::isfinite(pr.displaced_mass_kg)) {
    throw InputError("displaced_mass_kg", "buoyancy must be positive", "give rho * V of the planned water in kg");
  }
  if (!finite(pr.cb_m)) throw InputError("cb", "centre of buoyancy is not finite", "check the vehicle profile");
  for (std::size_t s = 0; s < pr.piece_sizes_kg.size(); ++s) {
    const double size = pr.piece_sizes_kg[s];
    if (!(size >= 0.01) || !std::isfinite(size)) {
      throw InputError("piece_sizes_kg[" + std::to_string(s) + "]", "piece size must be at least 10 g",
                       "list the kit's piece sizes in kg, e.g. 1.2, 2.4, 4.8");
    }
    if (s > 0 && !(size > pr.piece_sizes_kg[s - 1])) {
      throw InputError("piece_sizes_kg", "sizes must be ascending and distinct", "sort the sizes, e.g. 1.2, 2.4, 4.8");
    }
  }
  if (!pr.installed.empty() && pr.installed.size() != pr.points.size()) {
    throw InputError("installed", "expected one row per adjustment point (" + std::to_string(pr.points.size()) +
                                      "), got " + std::to_string(pr.installed.size()),
                     "give installed[point][size], or leave it empty when nothing is installed");
  }
  for (std::size_t p = 0; p < pr.installed.size(); ++p) {
    const auto& row = pr.installed[p];
    if (row.size() > pr.piece_sizes_kg.size()) {
      throw InputError("installed." + pr.points[p].name, "more sizes than the kit has",
                       "give one count per piece size");
    }
    for (int c : row) {
      if (c < 0) throw InputError("installed." + pr.points[p].name, "negative piece count", "counts are >= 0");
    }
  }
  for (const AdjustmentPoint& pt : pr.points) {
    if (!(pt.capacity_kg >= 0.0) || !std::isfinite(pt.capacity_kg) || !finite(pt.position_m)) {
      throw InputError("points." + pt.name, "capacity must be >= 0 and the position finite",
                       "check the adjustment point in the vehicle profile");
    }
  }
  const TrimSpec& s = pr.spec;
  if (!(s.net_buoyancy_max_kg >= std::max(0.0, s.net_buoyancy_min_kg)) || !std::isfinite(s.net_buoyancy_max_kg)) {
    throw InputError("spec.net_buoyancy_max_kg", "the band must contain a non-negative net buoyancy",
                     "give 0 <= min <= max, e.g. 0 and 1.2 kg");
  }
  if (!(s.pitch_tolerance_deg > 0.0) || !(s.roll_tolerance_deg > 0.0) || !(s.pitch_tolerance_deg < 45.0) ||
      !(s.roll_tolerance_deg < 45.0)) {
    throw InputError("spec", "pitch and roll tolerances must be in (0, 45) degrees", "e.g. 0.5 and 0.1");
  }
}

}  // namespace auv
