#pragma once
// Which channel each column of a SeaExplorer raw file becomes. Navigation
// files (`*.gli.sub.N`) name the vehicle's sensors and actuators, payload
// files (`*.pld1.raw.N`, `*.pld1.sub.N`) the science sensors; the mapping is
// the one of the SeaExplorer interchange CSV in ../shared (its README's
// column table): Depth -> depth, BallastPos -> pump_volume, LinPos ->
// battery_position, GPCTD_PRESSURE -> pressure ... Every other column is kept
// under its own name in lower case.
#include <string>
#include <string_view>

namespace auv::detail {

enum class SeaExplorerValue {
  kAsRecorded,
  kNmeaDegrees,   // ddmm.mmm (NMEA) -> decimal degrees
  kNonNegative,   // negative = "no reading" (Altitude -1 = no bottom detection)
  kHeading360,    // wrapped into [0, 360)
};

struct SeaExplorerColumn {
  std::string channel;  // "" = not imported (the payload's copy of navigation)
  std::string unit;     // the unit the vendor records it in ("" = none stated)
  SeaExplorerValue value = SeaExplorerValue::kAsRecorded;
  bool time = false;    // Timestamp / PLD_REALTIMECLOCK
  bool gps = false;     // Lat/Lon: a fix only at the surface when it changes
};

SeaExplorerColumn seaExplorerColumn(std::string_view header);

// ddmm.mmm -> degrees; NaN when the minutes are not below 60.
double nmeaToDegrees(double ddmm);

}  // namespace auv::detail
