#include "firstmission/water_conditions.h"

#include <cmath>

#include "common/input_error.h"
#include "seawater/seawater.h"

namespace auv {

WaterState resolveWater(const PlannedWater& w) {
  if (!std::isfinite(w.depth_m) || w.depth_m < 0.0 || w.depth_m > 11000.0) {
    throw InputError("depth", "operating depth must be between 0 and 11000 m", "give the planned depth in metres");
  }
  WaterState s;
  s.temperature_degC = w.temperature_degC;
  s.pressure_dbar = seawater::pressureFromDepth(w.depth_m, w.latitude_deg);
  s.density_kgm3 = seawater::density(w.salinity_psu, w.temperature_degC, s.pressure_dbar);
  return s;
}

}  // namespace auv
