#pragma once
// Date and time texts of vendor logs that are not ISO 8601 (which iso8601.h
// reads): `dd.mm.yyyy hh:mm:ss[.fff]` (European loggers), a bare time of day,
// a bare date, and the CF `units` of a NetCDF time variable. All UTC unless a
// zone says otherwise.
#include <optional>
#include <string_view>

namespace auv {

// `dd.mm.yyyy`, optionally followed by ' ', 'T' or '_' and hh:mm[:ss[.fff]].
// Seconds since 1970 UTC, nullopt for anything else or an impossible date.
std::optional<double> parseDayMonthYear(std::string_view text);

// A date alone: `dd.mm.yyyy` or `yyyy-mm-dd`; seconds since 1970 at 00:00 UTC.
std::optional<double> parseDateOnly(std::string_view text);

// `hh:mm[:ss[.fff]]` -> seconds since midnight (0 <= h < 24 ... 60 for leap seconds).
std::optional<double> parseTimeOfDay(std::string_view text);

// CF time units "<unit> since <reference>", e.g. "seconds since 1970-01-01T00:00:00Z"
// or "days since 1950-1-1 00:00:00 UTC": epoch seconds = value * scale + offset.
struct CfTimeUnits {
  double scale = 1.0;
  double offset = 0.0;
};
std::optional<CfTimeUnits> parseCfTimeUnits(std::string_view units);

// Days since 1970-01-01 of a proleptic Gregorian date; nullopt when invalid.
std::optional<long long> civilDays(long long year, int month, int day);

}  // namespace auv
