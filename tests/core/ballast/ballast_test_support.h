#pragma once
// Shared by the ballast tests: small vehicles built by hand, and the
// objective of docs/decisions/ballast-objective.md re-implemented from its
// text (not from the solver's code) so that tests can score any move.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ballast/ballast_problem.h"
#include "ballast/ballast_solution.h"
#include "common/units.h"

namespace auv::testing {

// Four points at (+-ax, +-ay, 0), CB at the origin, CG at cg.
inline BallastProblem boxVehicle(double mass_kg, double light_kg, const Eigen::Vector3d& cg,
                                 std::vector<double> sizes = {1.2, 2.4, 4.8}, double capacity_kg = 20.0,
                                 double ax = 1.0, double ay = 0.3) {
  BallastProblem p;
  p.vehicle.mass_kg = mass_kg;
  p.vehicle.cg_m = cg;
  p.vehicle.moment_kgm = mass_kg * cg;
  p.displaced_mass_kg = mass_kg + light_kg;
  p.cb_m = Eigen::Vector3d::Zero();
  const char* names[4] = {"fs", "fp", "as", "ap"};
  const double sx[4] = {1, 1, -1, -1}, sy[4] = {1, -1, 1, -1};
  for (int i = 0; i < 4; ++i) {
    AdjustmentPoint pt;
    pt.name = names[i];
    pt.label = names[i];
    pt.position_m = {sx[i] * ax, sy[i] * ay, 0.0};
    pt.capacity_kg = capacity_kg;
    p.points.push_back(pt);
  }
  p.piece_sizes_kg = std::move(sizes);
  return p;
}

// The objective's quantities for a predicted state (net, CG).
struct Scored {
  double negative_kg = 0, band_kg = 0;    // buoyancy class
  double pitch_x = 0, roll = 0;           // rad: atan2(-d_x, d_z), atan2(d_y, d_z)
  double pitch_violation = 0, roll_violation = 0, residual = 0;
  int effort = 0, removals = 0;
};

inline double outside(double v, double lo, double hi) { return v < lo ? lo - v : (v > hi ? v - hi : 0.0); }

inline Scored scoreState(const BallastProblem& p, double net_kg, const Eigen::Vector3d& d) {
  Scored s;
  const double lo = std::max(0.0, p.spec.net_buoyancy_min_kg), hi = p.spec.net_buoyancy_max_kg;
  s.negative_kg = std::max(0.0, -net_kg);
  s.band_kg = outside(net_kg, lo, hi);
  s.pitch_x = std::atan2(-d.x(), d.z());
  s.roll = std::atan2(d.y(), d.z());
  const double tp = units::degToRad(p.spec.pitch_tolerance_deg), tr = units::degToRad(p.spec.roll_tolerance_deg);
  s.pitch_violation = outside(s.pitch_x, -tp, tp);
  s.roll_violation = outside(s.roll, -tr, tr);
  s.residual = (s.pitch_x / tp) * (s.pitch_x / tp) + (s.roll / tr) * (s.roll / tr);
  return s;
}

inline Scored scoreSolution(const BallastProblem& p, const BallastSolution& sol) {
  const double W = p.displaced_mass_kg - sol.net_buoyancy_kg;
  Scored s = scoreState(p, sol.net_buoyancy_kg, W * sol.cg_m - p.displaced_mass_kg * p.cb_m);
  for (const auto& row : sol.delta) {
    for (int d : row) {
      s.effort += std::abs(d);
      s.removals += std::max(0, -d);
    }
  }
  return s;
}

inline int installedAt(const BallastProblem& p, std::size_t point, std::size_t size) {
  return point < p.installed.size() && size < p.installed[point].size() ? p.installed[point][size] : 0;
}

}  // namespace auv::testing
