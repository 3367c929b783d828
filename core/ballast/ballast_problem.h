#pragma once
// What the ballast solver is asked: the vehicle as it is now, the water it
// will dive in, where pieces may go, which pieces exist and which are already
// installed, and the acceptance bands (thesis §5.1 item 7).
#include <Eigen/Core>
#include <vector>

#include "hydrostatics/mass_properties.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

// HalfWay: aim at half of the needed change (Seaglider practice when the
// estimate is uncertain) but still never end negatively buoyant.
enum class BallastPolicy { Exact, HalfWay };

struct BallastProblem {
  MassProperties vehicle;                   // as it is now, installed pieces included
  double displaced_mass_kg = 0;             // rho * V at the planned water (buoyancy in kg)
  Eigen::Vector3d cb_m = Eigen::Vector3d::Zero();
  std::vector<AdjustmentPoint> points;      // from the profile
  std::vector<double> piece_sizes_kg;       // usable sizes (ascending)
  std::vector<std::vector<int>> installed;  // installed[point][size] = pieces present now; empty = none
  TrimSpec spec;                            // net buoyancy band, pitch/roll tolerances in deg
  BallastPolicy policy = BallastPolicy::Exact;
};

// Throws InputError naming the offending field (sizes, installed counts,
// capacities, masses, spec) so that front ends can show it.
void validateBallastProblem(const BallastProblem& problem);

// installed[p][s], or 0 when `installed` is empty.
int installedCount(const BallastProblem& problem, std::size_t point, std::size_t size);
double installedMassKg(const BallastProblem& problem, std::size_t point);

}  // namespace auv
