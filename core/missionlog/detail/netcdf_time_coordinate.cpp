#include "missionlog/detail/netcdf_time_coordinate.h"

#include <cmath>
#include <string_view>

#include "common/input_error.h"

namespace auv::detail {

std::optional<TimeCoordinate> findTimeCoordinate(const std::vector<NcVariable>& vars,
                                                 const std::vector<std::size_t>& members,
                                                 const std::string& dimension) {
  auto preference = [&](const NcVariable& v) {
    static constexpr std::string_view kNames[] = {"TIME", "time", "ctd_time"};
    for (std::size_t i = 0; i < 3; ++i)
      if (v.name == kNames[i]) return static_cast<int>(i);
    return v.name == dimension ? 3 : 4;
  };
  std::optional<TimeCoordinate> best;
  for (std::size_t k : members) {
    const auto units = parseCfTimeUnits(vars[k].units);
    if (!units) continue;
    if (!best || preference(vars[k]) < preference(vars[best->variable])) best = TimeCoordinate{k, *units};
  }
  return best;
}

void listTimeLikeVariables(const std::vector<NcVariable>& vars, const std::vector<std::size_t>& members,
                           std::string& list) {
  for (std::size_t k : members) {
    const std::string l = vars[k].name;
    if (l == "time" || l == "TIME" || l.find("time") != std::string::npos)
      list += (list.empty() ? "" : ", ") + l + " [" + vars[k].units + "]";
  }
}

void requireGregorianCalendar(const NcVariable& tv, const std::string& file) {
  if (!tv.calendar.empty() && tv.calendar != "standard" && tv.calendar != "gregorian" &&
      tv.calendar != "proleptic_gregorian")
    throw InputError(tv.name, "calendar \"" + tv.calendar + "\" is not the standard Gregorian calendar",
                     "write the time with calendar \"standard\" (every real clock uses it)", {file, 0, 0});
}

void decodeCfTime(std::vector<double>& values, const CfTimeUnits& units) {
  for (double& x : values)
    if (!std::isnan(x)) x = x * units.scale + units.offset;
}

}  // namespace auv::detail
