#pragma once
// The water of the next mission as the planner needs it: the operating point
// where the acceptance band applies, and every other point the vehicle will
// pass through, where it must still not be heavy. A vehicle that loses power
// rises through the column; if it is heavy anywhere on the way (usually the
// warm, fresh, shallow water, or deep down when the hull compresses more than
// seawater) it stops there instead of surfacing.
#include <string>
#include <vector>

#include "firstmission/water_conditions.h"

namespace auv {

struct NextMissionWater {
  PlannedWater operating;              // where net buoyancy should be in band
  std::vector<PlannedWater> transit;   // also never negative here (e.g. surface, deepest point)
  double temperature_sigma_degC = 0.5; // how well the operator knows the water (1 sigma)
  double salinity_sigma_psu = 0.2;
  std::string source;                  // "operator" or "last mission"
};

// Operating point plus the surface with the same water (launch and recovery)
// and, if deeper than the operating depth, the deepest planned point.
NextMissionWater nextMissionWater(const PlannedWater& operating, double deepest_m, const std::string& source);

struct ResolvedPoint {
  PlannedWater planned;
  WaterState state;      // in situ density (EOS-80 with pressure), temperature, pressure
  double displaced_kg = 0.0;  // rho V(T, p)
};

}  // namespace auv
