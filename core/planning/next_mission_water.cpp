#include "planning/next_mission_water.h"

namespace auv {

NextMissionWater nextMissionWater(const PlannedWater& operating, double deepest_m, const std::string& source) {
  NextMissionWater n;
  n.operating = operating;
  n.source = source;
  PlannedWater surface = operating;
  surface.depth_m = 0.0;
  if (operating.depth_m > 0.0) n.transit.push_back(surface);
  if (deepest_m > operating.depth_m) {
    PlannedWater deep = operating;
    deep.depth_m = deepest_m;
    n.transit.push_back(deep);
  }
  return n;
}

}  // namespace auv
