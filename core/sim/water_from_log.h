#pragma once
// The water a recording flew through, as a WaterColumn: the log's
// temperature and salinity against depth, averaged in depth bins and turned
// into in-situ density by core seawater (EOS-80 with pressure), exactly as
// for a CTD cast. Lets a replay fly in the recorded water.
#include "missionlog/mission_log.h"
#include "sim/water_column.h"

namespace auv::sim {

// Needs depth, temperature and salinity channels (InputError naming the one
// that is missing or empty). Bins of `bin_m`; the table reaches `margin_m`
// below the deepest sample.
WaterColumn waterColumnFromLog(const MissionLog& log, double bin_m = 1.0, double latitude_deg = 45.0,
                               double margin_m = 10.0);

}  // namespace auv::sim
