#pragma once
// The pitch and elevator at which an AUV holds depth at a given speed: the
// heave and pitch balance of auv_steady_model.h solved forward, for a
// vehicle of known weight, buoyancy and CG. This is the relation between CG,
// net buoyancy and flying pitch that the thesis says does not exist (§5.3.2):
// on the HUGIN model a millimetre of CG x moves the pitch at rest by 2.9 deg
// but the pitch in flight by only ~0.1 deg, a kilogram of net buoyancy by
// ~0.2 deg; the planner uses it to predict the pitch the next mission flies.
#include "analysis/auv_steady_model.h"

namespace auv::analysis {

struct LevelFlightInput {
  double weight_n = 0.0, buoyancy_n = 0.0;
  double x_g_m = 0.0;   // CG - CB along x
  double bg_m = 0.0;    // CG below CB
  double speed_mps = 0.0;
  double density_kgm3 = 1025.0;
  double roll_rad = 0.0;
  double depth_rate_mps = 0.0;  // positive descending; 0 = level flight
};

struct LevelFlight {
  bool ok = false;          // false: no balance within +-30 deg of pitch (or no planes to trim with)
  double pitch_rad = 0.0;   // nose up positive
  double elevator_deg = 0.0;  // interchange convention (trailing edge down positive)
};

LevelFlight solveLevelFlight(const SteadyHydroCoefficients& c, const LevelFlightInput& in);

}  // namespace auv::analysis
