#pragma once
// The CF time coordinate of a NetCDF dimension: which of its variables holds
// the time, in which calendar, and its values decoded to seconds since 1970
// (the `units` text itself is read by time_text.h).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "missionlog/detail/netcdf_variable.h"
#include "missionlog/time_text.h"

namespace auv::detail {

struct TimeCoordinate {
  std::size_t variable = 0;  // index into the variables
  CfTimeUnits units;
};

// Among `members` (indices into `vars`) with CF time units "<unit> since
// <date>": TIME, then time, then ctd_time, then the variable named after the
// dimension, then the first. nullopt when none has such units.
std::optional<TimeCoordinate> findTimeCoordinate(const std::vector<NcVariable>& vars,
                                                 const std::vector<std::size_t>& members,
                                                 const std::string& dimension);

// Appends "<name> [<units>]" of the members whose name says time, for the
// message when no dimension has a time coordinate.
void listTimeLikeVariables(const std::vector<NcVariable>& vars, const std::vector<std::size_t>& members,
                           std::string& list);

// Throws InputError (naming `file`) for a calendar other than the standard
// Gregorian one; an absent calendar attribute means standard.
void requireGregorianCalendar(const NcVariable& time, const std::string& file);

// Values in the time variable's units -> seconds since 1970 UTC; NaN stays.
void decodeCfTime(std::vector<double>& values, const CfTimeUnits& units);

}  // namespace auv::detail
