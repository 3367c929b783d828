#include "missionlog/channel_aliases.h"

#include <utility>

#include "missionlog/detail/ascii_text.h"
#include "missionlog/log_table.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"

namespace auv {
namespace {

using detail::trim;

struct AliasEntry {
  std::string_view key;
  std::string_view channel;
  std::string_view unit;
};

// Generic names carry no unit: a header without one gets the format's unit
// and a report note. Slocum sensor names carry the unit the Slocum masterdata
// defines (m_pitch is always in rad), so no note is needed for them.
constexpr AliasEntry kAliases[] = {
    // time
    {"t", "time", ""},               {"timestamp", "time", ""},     {"time_stamp", "time", ""},
    {"datetime", "time", ""},        {"date_time", "time", ""},     {"utc", "time", ""},
    {"utc_time", "time", ""},        {"time_utc", "time", ""},      {"unix_time", "time", ""},
    {"epoch", "time", ""},           {"epoch_time", "time", ""},    {"elapsed_time", "time", ""},
    {"mission_time", "time", ""},    {"nav_time", "time", ""},      {"seconds", "time", ""},
    {"m_present_time", "time", "timestamp"}, {"sci_m_present_time", "time", "timestamp"},
    {"date", "date", ""},            {"day", "date", ""},
    // depth
    {"m_depth", "depth", "m"},       {"measured_depth", "depth", ""}, {"actual_depth", "depth", ""},
    {"depth_measured", "depth", ""}, {"vehicle_depth", "depth", ""},  {"nav_depth", "depth", ""},
    {"depth_nav", "depth", ""},
    {"commanded_depth", "depth_cmd", ""}, {"depth_command", "depth_cmd", ""},
    {"depth_commanded", "depth_cmd", ""}, {"cmd_depth", "depth_cmd", ""},
    {"command_depth", "depth_cmd", ""},   {"depth_setpoint", "depth_cmd", ""},
    {"depth_set_point", "depth_cmd", ""}, {"depth_set", "depth_cmd", ""},
    {"set_depth", "depth_cmd", ""},       {"depth_ref", "depth_cmd", ""},
    {"depth_reference", "depth_cmd", ""}, {"desired_depth", "depth_cmd", ""},
    {"depth_demand", "depth_cmd", ""},    {"demanded_depth", "depth_cmd", ""},
    {"alt", "altitude", ""},         {"m_altitude", "altitude", "m"}, {"height_above_bottom", "altitude", ""},
    {"altimeter", "altitude", ""},   {"dvl_altitude", "altitude", ""},
    // attitude
    {"m_pitch", "pitch", "rad"},     {"pitch_angle", "pitch", ""},  {"nav_pitch", "pitch", ""},
    {"pitch_nav", "pitch", ""},
    {"c_pitch", "pitch_cmd", "rad"}, {"commanded_pitch", "pitch_cmd", ""},
    {"pitch_command", "pitch_cmd", ""}, {"pitch_commanded", "pitch_cmd", ""},
    {"cmd_pitch", "pitch_cmd", ""},  {"pitch_setpoint", "pitch_cmd", ""},
    {"pitch_set_point", "pitch_cmd", ""}, {"pitch_ref", "pitch_cmd", ""},
    {"pitch_reference", "pitch_cmd", ""}, {"desired_pitch", "pitch_cmd", ""},
    {"pitch_demand", "pitch_cmd", ""},
    {"m_roll", "roll", "rad"},       {"roll_angle", "roll", ""},    {"nav_roll", "roll", ""},
    {"roll_nav", "roll", ""},
    {"m_heading", "heading", "rad"}, {"hdg", "heading", ""},        {"yaw", "heading", ""},
    {"compass_heading", "heading", ""}, {"nav_heading", "heading", ""},
    {"c_heading", "heading_cmd", "rad"}, {"commanded_heading", "heading_cmd", ""},
    {"heading_command", "heading_cmd", ""}, {"heading_setpoint", "heading_cmd", ""},
    // motion and actuators
    {"forward_speed", "speed", ""},  {"forward_velocity", "speed", ""}, {"velocity", "speed", ""},
    {"u", "speed", ""},              {"surge_velocity", "speed", ""}, {"surge_speed", "speed", ""},
    {"speed_through_water", "speed", ""}, {"stw", "speed", ""},     {"water_speed", "speed", ""},
    {"rpm", "prop_rpm", ""},         {"propeller_rpm", "prop_rpm", ""}, {"propeller_speed", "prop_rpm", ""},
    {"prop_speed", "prop_rpm", ""},  {"motor_rpm", "prop_rpm", ""}, {"thruster_rpm", "prop_rpm", ""},
    {"motor_speed", "prop_rpm", ""}, {"shaft_rpm", "prop_rpm", ""},
    {"stern_plane", "elevator", ""}, {"sternplane", "elevator", ""}, {"stern_planes", "elevator", ""},
    {"elevator_angle", "elevator", ""},
    {"rudder_angle", "rudder", ""},  {"m_fin", "rudder", "rad"},    {"c_fin", "rudder_cmd", "rad"},
    {"m_battpos", "battery_position", "in"}, {"battpos", "battery_position", ""},
    {"c_battpos", "battery_position_cmd", "in"},
    {"m_de_oil_vol", "pump_volume", "cm3"}, {"m_ballast_pumped", "pump_volume", "cm3"},
    {"c_de_oil_vol", "pump_volume_cmd", "cm3"}, {"c_ballast_pumped", "pump_volume_cmd", "cm3"},
    {"vbd", "pump_volume", ""},      {"vbd_volume", "pump_volume", ""}, {"ballast_volume", "pump_volume", ""},
    {"oil_volume", "pump_volume", ""},
    {"total_power", "power", ""},    {"power_total", "power", ""},
    // water
    {"temp", "temperature", ""},     {"water_temp", "temperature", ""}, {"water_temperature", "temperature", ""},
    {"sea_temp", "temperature", ""}, {"sea_temperature", "temperature", ""}, {"ctd_temp", "temperature", ""},
    {"ctd_temperature", "temperature", ""}, {"sea_water_temperature", "temperature", ""},
    {"sci_water_temp", "temperature", "degC"},
    {"sal", "salinity", ""},         {"psal", "salinity", ""},      {"practical_salinity", "salinity", ""},
    {"ctd_salinity", "salinity", ""}, {"sea_water_salinity", "salinity", ""},
    {"cond", "conductivity", ""},    {"cndc", "conductivity", ""},  {"ctd_conductivity", "conductivity", ""},
    {"sci_water_cond", "conductivity", "S/m"},
    {"pres", "pressure", ""},        {"water_pressure", "pressure", ""}, {"ctd_pressure", "pressure", ""},
    {"sea_pressure", "pressure", ""}, {"sci_water_pressure", "pressure", "bar"},
};

bool isSeparator(char c) { return c == ' ' || c == '\t' || c == '-' || c == '.' || c == '/' || c == '_'; }

bool knownUnit(std::string_view u) { return !u.empty() && isKnownUnit(normaliseUnitSpelling(u)); }

bool knownChannel(std::string_view key) {
  return key == "time" || !canonicalUnitFor(key).empty() || findChannelAlias(key).has_value();
}

}  // namespace

std::string normaliseChannelKey(std::string_view name) {
  std::string out;
  out.reserve(name.size());
  bool pendingSep = false;
  for (char c : name) {
    if (isSeparator(c)) {
      pendingSep = !out.empty();
      continue;
    }
    if (pendingSep) out += '_';
    pendingSep = false;
    out += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  return out;
}

std::optional<ChannelAlias> findChannelAlias(std::string_view key) {
  if (key.empty()) return std::nullopt;
  if (key == "time") return ChannelAlias{"time", ""};
  for (const auto& a : kAliases)
    if (a.key == key) return ChannelAlias{std::string(a.channel), a.unit};
  const std::string_view canonical = canonicalUnitFor(key);
  if (!canonical.empty()) return ChannelAlias{std::string(key), ""};
  return std::nullopt;
}

HeaderField parseHeaderField(std::string_view cell) {
  HeaderField f;
  const std::string utf8 = toValidUtf8(cell);
  std::string_view t = trim(utf8);
  if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = trim(t.substr(1, t.size() - 2));
  f.text = std::string(t);
  std::string_view name = t, unit;
  if (!t.empty() && (t.back() == ']' || t.back() == ')' || t.back() == '}')) {
    const char close = t.back();
    const char open = close == ']' ? '[' : close == ')' ? '(' : '{';
    const auto at = t.rfind(open);
    if (at != std::string_view::npos && at > 0) {
      name = trim(t.substr(0, at));
      unit = trim(t.substr(at + 1, t.size() - at - 2));
    }
  } else if (const auto slash = t.rfind(" / "); slash != std::string_view::npos && knownUnit(trim(t.substr(slash + 3)))) {
    name = trim(t.substr(0, slash));
    unit = trim(t.substr(slash + 3));
  }
  f.name = std::string(name);
  f.unit = std::string(unit);
  f.key = normaliseChannelKey(name);
  if (unit.empty() && !knownChannel(f.key)) {
    const auto us = f.key.rfind('_');
    if (us != std::string::npos && us > 0) {
      const std::string prefix = f.key.substr(0, us);
      // The suffix is taken from the written name so that "Depth_M" keeps its case.
      const auto nameUs = f.name.rfind('_');
      const std::string_view suffix = nameUs == std::string::npos ? std::string_view(f.key).substr(us + 1)
                                                                  : std::string_view(f.name).substr(nameUs + 1);
      if (knownChannel(prefix) && knownUnit(suffix)) {
        f.unit = std::string(suffix);
        f.name = nameUs == std::string::npos ? prefix : f.name.substr(0, nameUs);
        f.key = prefix;
      }
    }
  }
  return f;
}

}  // namespace auv
