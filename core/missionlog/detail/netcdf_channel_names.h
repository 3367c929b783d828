#pragma once
// Which channel each NetCDF variable becomes: the known variables of the
// Seaglider basestation or IOOS/OG1 trajectory files under the format's names
// (docs/decisions/readers-netcdf-variables.md), then CF standard names, then
// the variable's own name.
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "missionlog/detail/netcdf_variable.h"

namespace auv::detail {

struct ChannelName {
  std::string name;
  double scale = 1.0;       // e.g. -1 where the file counts the other way
  std::string to_unit;      // extra channels: convert to this ("" = keep)
  std::string force_unit;   // the file's unit label is known to be wrong ("" = trust it)
};

// The channels of one dimension's variables `members` (indices into `vars`,
// in file order), leaving out the time variable and <name>_qc / <NAME>_QC
// flags; in the order of `members`. A known name goes to the first variable
// present that claims it; the others keep their own names, prefixed "nc_"
// where that would collide or pose as a format channel.
std::vector<std::pair<std::size_t, ChannelName>> nameChannels(const std::vector<NcVariable>& vars,
                                                              const std::map<std::string, std::size_t>& byName,
                                                              const std::vector<std::size_t>& members,
                                                              std::size_t timeVar, bool seaglider);

// The channels an analysis looks for that are not in `found`, comma-separated.
std::string missingChannels(const std::set<std::string>& found);

}  // namespace auv::detail
