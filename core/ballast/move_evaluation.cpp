#include <algorithm>
#include <cmath>

#include "ballast/ballast_solver.h"
#include "common/input_error.h"
#include "common/units.h"
#include "hydrostatics/static_trim.h"

namespace auv {

BallastSolution evaluateMove(const BallastProblem& pr, const std::vector<std::vector<int>>& delta) {
  if (delta.size() != pr.points.size()) {
    throw InputError("delta", "expected one row per adjustment point", "give delta[point][size]");
  }
  BallastSolution sol;
  sol.delta = delta;
  double added = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (std::size_t p = 0; p < pr.points.size(); ++p) {
    if (delta[p].size() != pr.piece_sizes_kg.size()) {
      throw InputError("delta." + pr.points[p].name, "expected one count per piece size", "give delta[point][size]");
    }
    double m = 0.0;
    for (std::size_t s = 0; s < delta[p].size(); ++s) m += delta[p][s] * pr.piece_sizes_kg[s];
    sol.add_kg.push_back(m);
    added += m;
    moment += m * pr.points[p].position_m;
  }
  const double W = pr.vehicle.mass_kg + added;
  const Eigen::Vector3d first_moment = pr.vehicle.mass_kg * pr.vehicle.cg_m + moment;
  sol.cg_m = first_moment / W;
  sol.net_buoyancy_kg = pr.displaced_mass_kg - W;
  const StaticTrim trim = staticTrim(units::g0 * W, units::g0 * pr.displaced_mass_kg, sol.cg_m, pr.cb_m);
  sol.pitch_deg = units::radToDeg(trim.pitch_rad);
  sol.roll_deg = units::radToDeg(trim.roll_rad);
  // Same closeness as the solver's own bookkeeping (0.1 g quanta, 1e-12 rad).
  constexpr double kKg = 1e-6, kDeg = 1e-9;
  sol.buoyancy_in_band = sol.net_buoyancy_kg >= std::max(0.0, pr.spec.net_buoyancy_min_kg) - kKg &&
                         sol.net_buoyancy_kg <= pr.spec.net_buoyancy_max_kg + kKg;
  sol.pitch_in_band = std::abs(sol.pitch_deg) <= pr.spec.pitch_tolerance_deg + kDeg;
  sol.roll_in_band = std::abs(sol.roll_deg) <= pr.spec.roll_tolerance_deg + kDeg;
  return sol;
}

}  // namespace auv
