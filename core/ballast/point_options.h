#pragma once
// Every distinct mass change one adjustment point can take with the kit,
// each with the cheapest way to make it (fewest pieces handled, then fewest
// removals). The solver only needs the mass change per point: pieces of any
// size at the same point act the same on weight and CG.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace auv::ballast {

struct PointOptions {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  int sizes = 0;
  std::vector<std::int64_t> mass_q;  // signed change, ascending, unique
  std::vector<double> mass_kg;
  std::vector<int> effort;    // pieces handled
  std::vector<int> removals;  // pieces taken out
  std::vector<int> delta;     // [option * sizes + size], signed counts

  std::size_t count() const { return mass_q.size(); }
  const int* deltaOf(std::size_t option) const { return delta.data() + option * static_cast<std::size_t>(sizes); }
};

// sizes_q: piece sizes in quanta (> 0); installed: pieces per size now at
// the point (may be empty); capacity_q: most adjustment mass after the move.
// Removing everything is always possible, so the result is never empty.
PointOptions pointOptions(const Eigen::Vector3d& position_m, const std::vector<std::int64_t>& sizes_q,
                          const std::vector<int>& installed, std::int64_t capacity_q);

}  // namespace auv::ballast
