#pragma once
// Slocum sensors -> mission-log channels, shared by the dbd2asc text reader
// and the native binary reader so both give the same log for the same data:
// sensors in the alias table (channel_aliases.cpp: m_depth -> depth, m_pitch
// rad -> pitch deg, m_battpos in -> battery_position mm, sci_water_* ...)
// become the format's channels, every other sensor is kept under its own name
// and unit, latitude/longitude in the glider's ddmm.mmmm form become degrees.
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/log_table.h"

namespace auv::detail {

// Slocum writes this for a latitude/longitude without a fix.
inline constexpr double kSlocumNoFix = 69696969.0;

// NMEA-style ddmm.mmmm (Slocum units "lat"/"lon") -> decimal degrees; NaN
// for the no-fix value.
double slocumNmeaToDegrees(double ddmm);

// The time sensors, which are the row clock and not channels.
inline bool isSlocumEngineeringTime(std::string_view s) { return s == "m_present_time"; }
inline bool isSlocumScienceTime(std::string_view s) { return s == "sci_m_present_time"; }

// The column of one sensor (no values yet). `nmea` is set for lat/lon units.
TableColumn slocumColumn(const std::string& sensor, const std::string& unit, const InputLocation& where, bool& nmea);

// Engineering and science tables (same column layout, either may have no
// rows) -> one log: a channel claimed by two sensors goes to the one with more
// samples, the streams are tidied and merged on time, the header tags become
// metadata (plus the glider's name from the file name).
MissionLog finishSlocumLog(std::vector<LogTable> streams, std::vector<MetadataEntry> tags, const ReadOptions& options,
                           ReadReport& report);

}  // namespace auv::detail
