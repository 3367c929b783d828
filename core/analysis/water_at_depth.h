#pragma once
// The water the vehicle flew in, inside the analysis windows: temperature,
// salinity, density, pressure and depth from the CTD's own samples, overall
// and per window.
#include <string>
#include <vector>

#include "analysis/segments.h"
#include "analysis/statistics.h"
#include "missionlog/mission_log.h"

namespace auv::analysis {

struct WaterAtDepth {
  MeanEstimate T, S, rho, p, z;
  // Per window (NaN where the window has no CTD sample): the segment's own water.
  std::vector<double> win_rho, win_T, win_p;
  std::string salinity_source, density_source;
  std::size_t skipped = 0;
};

// Water properties on the CTD's own time base inside the windows (and deeper
// than min_depth_m). Salinity from the log, else PSS-78 from conductivity;
// density from the log, else EOS-80 in situ at the sample's pressure.
// in_overall (optional, one per window): false = the window gets its own
// water but does not count in the overall (operating-depth) means.
WaterAtDepth waterProperties(const MissionLog& log, const std::vector<Segment>& win, const TimeSeries& depth,
                             double latitude, double min_depth_m, SeriesModel model,
                             const std::vector<bool>* in_overall = nullptr);

}  // namespace auv::analysis
