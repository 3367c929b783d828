#pragma once
// How vendor column names map to the channels of the mission-log model:
// `Depth(m)`, `depth_m`, `DEPTH [m]` and `m_depth` are all the measured depth.
// Shared by the delimited-text and Slocum readers (the NetCDF reader has its
// own variable table because CF names are not header texts).
#include <optional>
#include <string>
#include <string_view>

namespace auv {

// One header cell split into name and unit.
struct HeaderField {
  std::string text;  // trimmed and unquoted
  std::string name;  // without the unit
  std::string unit;  // as written, "" when the cell has none
  std::string key;   // `name` normalised for matching (see normaliseChannelKey)
};

// Units are taken from a trailing `[u]`, `(u)` or `{u}`, from ` / u`, or from
// a `_u` suffix when the rest is a known channel and `u` a known unit
// (`depth_m`, `pitch_cmd_deg`, but not `m_depth`).
HeaderField parseHeaderField(std::string_view cell);

// Lower case, runs of blanks, '-', '.', '/' and '_' collapsed to one '_',
// no leading/trailing '_': "Water Temp." -> "water_temp".
std::string normaliseChannelKey(std::string_view name);

struct ChannelAlias {
  std::string channel;    // name in the log; "time" and "date" mark time columns
  std::string_view unit;  // the unit the source defines for it (static); "" = none defined
};

// The channel a normalised key stands for: the format's own names (and their
// _cmd/_est/_flightmodel variants) map to themselves, then the alias table
// (generic vendor names, Slocum sensor names). nullopt for anything else,
// which readers keep as an extra channel under its normalised key.
std::optional<ChannelAlias> findChannelAlias(std::string_view key);

}  // namespace auv
