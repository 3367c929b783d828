#pragma once
// Units of the mission-log interchange format. The unit written in a column
// header is authoritative: columns named in the format table (and their
// `_cmd`, `_est`, `_flightmodel` variants) are converted to the table's
// canonical unit on import, so the analysis never has to ask whether a pitch is
// in degrees or radians. Every other column keeps the unit it was written with.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace auv {

// value_canonical = value * scale + offset (offset only for temperatures).
struct UnitConversion {
  double scale = 1.0;
  double offset = 0.0;
  bool isIdentity() const { return scale == 1.0 && offset == 0.0; }
  double apply(double v) const { return v * scale + offset; }
};

// Canonical unit of a channel from the format table ("s" for time), or "" when
// the channel is not in the table and keeps its own unit. "heading_cmd" and
// "speed_flightmodel" map to "deg" and "m/s" through their base name.
std::string_view canonicalUnitFor(std::string_view channel);

// The base name a variant belongs to ("pitch_cmd" -> "pitch"), or the name
// itself when it has none of the known suffixes.
std::string_view baseChannelName(std::string_view channel);

// True if `unit` is a spelling this module knows (any quantity).
bool isKnownUnit(std::string_view unit);

// Conversion from `from` to `to`; nullopt when either unit is unknown or they
// measure different quantities (deg -> m). Spellings are normalised first
// ("°C", "cc", "kn").
std::optional<UnitConversion> unitConversion(std::string_view from, std::string_view to);

// Known spellings that convert to `canonical`, for error messages.
std::vector<std::string> unitsConvertibleTo(std::string_view canonical);

}  // namespace auv
