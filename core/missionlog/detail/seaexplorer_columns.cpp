#include "missionlog/detail/seaexplorer_columns.h"

#include <cmath>

#include "missionlog/detail/ascii_text.h"
#include "missionlog/log_table.h"
#include "missionlog/unit_conversion.h"

namespace auv::detail {
namespace {

struct Rule {
  std::string_view header;
  std::string_view channel;
  std::string_view unit;
  SeaExplorerValue value = SeaExplorerValue::kAsRecorded;
};

// Units as the vendor records them (ALSEAMAR SeaExplorer manual; checked
// against the ranges in the real files: BallastPos +-500 cm3, LinPos 40-100 mm).
constexpr Rule kRules[] = {
    // navigation (gli)
    {"depth", "depth", "m"},
    {"pitch", "pitch", "deg"},
    {"roll", "roll", "deg"},
    {"heading", "heading", "deg", SeaExplorerValue::kHeading360},
    {"desiredh", "heading_cmd", "deg", SeaExplorerValue::kHeading360},
    {"ballastpos", "pump_volume", "cm3"},
    {"ballastcmd", "pump_volume_cmd", "cm3"},
    {"linpos", "battery_position", "mm"},
    {"lincmd", "battery_position_cmd", "mm"},
    {"angpos", "roll_mass", "deg"},
    {"angcmd", "roll_mass_cmd", "deg"},
    {"altitude", "altitude", "m", SeaExplorerValue::kNonNegative},
    {"navstate", "nav_state", "1"},
    {"securitylevel", "security_level", "1"},
    {"voltage", "battery_voltage", "V"},
    {"pa", "internal_pressure", "Pa"},
    {"temperature", "internal_temperature", "degC"},
    {"declination", "declination", "deg"},
    // payload (pld1): Sea-Bird GPCTD and RBR Legato CTDs
    {"gpctd_pressure", "pressure", "dbar"},
    {"gpctd_temperature", "temperature", "degC"},
    {"gpctd_conductivity", "conductivity", "S/m"},
    {"legato_pressure", "pressure", "dbar"},
    {"legato_temperature", "temperature", "degC"},
    {"legato_conductivity", "conductivity", "mS/cm"},
    {"legato_salinity", "salinity", "PSU"},
};

}  // namespace

double nmeaToDegrees(double ddmm) {
  const double a = std::fabs(ddmm);
  const double deg = std::floor(a / 100.0);
  const double min = a - 100.0 * deg;
  if (!(min < 60.0) || deg > 180.0) return NAN;
  return std::copysign(deg + min / 60.0, ddmm);
}

SeaExplorerColumn seaExplorerColumn(std::string_view header) {
  const std::string key = lower(trim(header));
  SeaExplorerColumn c;
  if (key == "timestamp" || key == "pld_realtimeclock") {
    c.time = true;
    c.channel = "time";
    return c;
  }
  if (key == "lat" || key == "lon") {
    c.channel = key == "lat" ? "gps_lat" : "gps_lon";
    c.unit = "deg";
    c.value = SeaExplorerValue::kNmeaDegrees;
    c.gps = true;
    return c;
  }
  // The payload's copy of the navigation (NAV_DEPTH, NAV_LATITUDE ...) is
  // what the gli file records at its own rate; importing it twice would give
  // two depth channels that differ only by their time base.
  if (key.rfind("nav_", 0) == 0) return c;
  for (const Rule& r : kRules)
    if (key == r.header) {
      c.channel = std::string(r.channel);
      c.unit = std::string(r.unit);
      c.value = r.value;
      return c;
    }
  c.channel = safeChannelName(key);
  // An unknown column must not pose as a channel of the format.
  if (!canonicalUnitFor(c.channel).empty()) c.channel = "seaexplorer_" + c.channel;
  return c;
}

}  // namespace auv::detail
