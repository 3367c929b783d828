#pragma once
// Planned water for a mission as the operator states it (temperature,
// salinity, operating depth) turned into what hydrostatics needs: in-situ
// pressure and density. The thesis dropped pressure ("0.45 % at 1000 m");
// we keep it, because on a 1.5 m^3 hull that is ~7 kg.
#include "hydrostatics/balance.h"

namespace auv {

struct PlannedWater {
  double temperature_degC = 10.0;
  double salinity_psu = 35.0;
  double depth_m = 0.0;
  double latitude_deg = 45.0;
};

// Validates the inputs (InputError names the field) and returns the in-situ
// state: pressure from depth (UNESCO 1983), density EOS-80 with pressure.
WaterState resolveWater(const PlannedWater& planned);

}  // namespace auv
