#include "missionlog/unit_spelling.h"

#include <utility>
#include <vector>

#include "missionlog/detail/ascii_text.h"
#include "missionlog/unit_conversion.h"

namespace auv {
namespace {

using detail::lower;
using detail::trim;

// Lower-case spellings seen in Slocum (dbd2asc), CF/NetCDF and vendor text
// headers -> a spelling unit_conversion knows (or the house spelling of a unit
// it does not convert, such as kg/m3 for density).
constexpr std::pair<std::string_view, std::string_view> kAliases[] = {
    {"degc", "degC"},        {"deg_c", "degC"},       {"degrees_c", "degC"},
    {"degree_c", "degC"},    {"deg. c", "degC"},      {"degrees c", "degC"},
    {"celsius", "degC"},     {"degrees_celsius", "degC"}, {"degree_celsius", "degC"},
    {"\xC2\xBA" "c", "degC"},  // ºC (ordinal indicator, common in Spanish/Portuguese files)
    {"s m-1", "S/m"},        {"s/m", "S/m"},          {"s.m-1", "S/m"},
    {"ms cm-1", "mS/cm"},    {"ms/cm", "mS/cm"},      {"us cm-1", "uS/cm"},
    {"m.s-1", "m/s"},        {"m/sec", "m/s"},        {"cm s-1", "cm/s"},
    {"cm.s-1", "cm/s"},      {"mm s-1", "mm/s"},
    {"nodim", "1"},          {"bool", "1"},           {"enum", "1"},
    {"count", "1"},          {"counts", "1"},         {"none", "1"},
    {"dimensionless", "1"},  {"-", "1"},
    {"sec", "s"},            {"secs", "s"},           {"second", "s"},
    {"mins", "min"},         {"minutes", "min"},      {"minute", "min"},
    {"hours", "h"},          {"hour", "h"},           {"hr", "h"},
    {"degrees_north", "deg"}, {"degree_north", "deg"}, {"degrees_east", "deg"},
    {"degree_east", "deg"},  {"deg.", "deg"},         {"\xC2\xBA", "deg"},  // º
    {"decibars", "dbar"},    {"db", "dbar"},
    {"pss", "PSU"},          {"0.001", "PSU"},        {"1e-3", "PSU"},
    {"kg m-3", "kg/m3"},     {"kg/m^3", "kg/m3"},     {"1/min", "rpm"},
};

// Every spelling unit_conversion knows, reached through the canonical units
// of each quantity it converts.
const std::vector<std::string>& knownSpellings() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> v;
    for (std::string_view c : {"deg", "m", "dbar", "degC", "m/s", "S/m", "PSU", "cm3", "rpm", "W", "s", "1"})
      for (auto& u : unitsConvertibleTo(c)) v.push_back(std::move(u));
    return v;
  }();
  return all;
}

}  // namespace

std::string normaliseUnitSpelling(std::string_view unit) {
  unit = trim(unit);
  if (unit.empty() || isKnownUnit(unit)) return std::string(unit);
  const std::string l = lower(unit);
  for (const auto& [alias, spelling] : kAliases)
    if (alias == l) return std::string(spelling);
  // Case-insensitive match, only when it is unambiguous ("DBAR", "Deg", "RAD";
  // not "MS" which could be mS or ms).
  const std::string* hit = nullptr;
  for (const auto& s : knownSpellings())
    if (lower(s) == l) {
      if (hit && *hit != s) return std::string(unit);
      hit = &s;
    }
  return hit ? *hit : std::string(unit);
}

}  // namespace auv
