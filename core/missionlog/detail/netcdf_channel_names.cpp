#include "missionlog/detail/netcdf_channel_names.h"

#include <algorithm>
#include <span>
#include <string_view>

#include "missionlog/log_table.h"
#include "missionlog/unit_conversion.h"

namespace auv::detail {
namespace {

// Known variables: name (exact) -> channel. Order matters: the first one
// present in a dimension wins its channel, later ones keep their own names.
struct VarRule {
  std::string_view variable;
  std::string_view channel;
  double scale = 1.0;
  std::string_view to_unit = {};       // extra channels: convert to this
  std::string_view force_unit = {};    // the file's unit label is known to be wrong
};

constexpr VarRule kSeagliderRules[] = {
    {"depth", "depth"},
    {"pressure", "pressure"},
    {"eng_pitchAng", "pitch"},
    {"eng_rollAng", "roll"},
    {"eng_head", "heading"},
    // basestation gives eng_vbdCC no unit; it is the VBD volume in cm3.
    {"eng_vbdCC", "pump_volume", 1.0, {}, "cm3"},
    // Seaglider counts the pitch mass positive aft (nose up); the format
    // counts battery_position positive forward (nose down).
    {"eng_pitchCtl", "battery_position", -1.0},
    {"eng_rollCtl", "roll_mass"},
    // GC (guidance and control) commands at the start of each motor event;
    // basestation labels all three "cm": the VBD one is cm3, the roll one deg.
    {"gc_vbd_ctl", "pump_volume_cmd", 1.0, {}, "cm3"},
    {"gc_pitch_ctl", "battery_position_cmd", -1.0},
    {"gc_roll_ctl", "roll_mass_cmd", 1.0, {}, "deg"},
    {"log_gps_lat", "gps_lat"},
    {"log_gps_lon", "gps_lon"},
    {"temperature", "temperature"},
    {"salinity", "salinity"},
    {"conductivity", "conductivity"},
    // basestation labels in-situ density "g/m^3" but writes kg/m^3 (~1025).
    {"density_insitu", "density", 1.0, {}, "kg/m3"},
    {"speed", "speed_flightmodel"},
    {"glide_angle", "glide_angle_flightmodel"},
    {"vert_speed", "vert_speed_flightmodel", 1.0, "m/s"},
    {"buoyancy", "buoyancy_flightmodel"},
};

constexpr VarRule kTrajectoryRules[] = {
    {"DEPTH", "depth"},         {"depth", "depth"},
    {"PRES", "pressure"},       {"pressure", "pressure"},       {"PRESSURE", "pressure"},
    {"PITCH", "pitch"},         {"pitch", "pitch"},
    {"ROLL", "roll"},           {"roll", "roll"},
    {"HEADING", "heading"},     {"heading", "heading"},
    {"TEMP", "temperature"},    {"temperature", "temperature"}, {"TEMPERATURE", "temperature"},
    {"CNDC", "conductivity"},   {"conductivity", "conductivity"},
    {"PSAL", "salinity"},       {"salinity", "salinity"},
    {"DENSITY", "density"},     {"density", "density"},
    // OG1.0 vocabulary (OceanGliders format 1.0): the glider's own attitude
    // sensors and actuators.
    {"GLIDER_PITCH", "pitch"},  {"GLIDER_ROLL", "roll"},        {"GLIDER_HEADING", "heading"},
    {"HEADING_CMD", "heading_cmd"},
    {"VBD_CC", "pump_volume"},  {"VBD", "pump_volume"},         {"BALLAST_VOLUME", "pump_volume"},
    {"VBD_CMD", "pump_volume_cmd"},
    {"BATTERY_POSITION", "battery_position"},                   {"PITCH_MASS_POSITION", "battery_position"},
    {"ROLL_MASS", "roll_mass"}, {"ALTITUDE", "altitude"},       {"ALTI", "altitude"},
    {"GLIDER_SPEED", "speed"},  {"SPEED_THROUGH_WATER", "speed"},
    {"DEPTH_CMD", "depth_cmd"},
};

// CF standard names, for variables the tables above do not name.
constexpr std::pair<std::string_view, std::string_view> kStandardNames[] = {
    {"depth", "depth"},
    {"sea_water_pressure", "pressure"},
    {"platform_pitch", "pitch"},
    {"platform_pitch_fore_up", "pitch"},
    {"platform_roll", "roll"},
    {"platform_roll_starboard_down", "roll"},
    {"platform_orientation", "heading"},
    {"platform_yaw", "heading"},
    {"sea_water_temperature", "temperature"},
    {"sea_water_practical_salinity", "salinity"},
    {"sea_water_salinity", "salinity"},
    {"sea_water_electrical_conductivity", "conductivity"},
    {"sea_water_density", "density"},
};

// The channels an analysis looks for, to say which ones a file lacks.
constexpr std::string_view kExpected[] = {"depth", "pitch", "roll", "heading", "temperature", "salinity", "pressure"};

}  // namespace

std::vector<std::pair<std::size_t, ChannelName>> nameChannels(const std::vector<NcVariable>& vars,
                                                              const std::map<std::string, std::size_t>& byName,
                                                              const std::vector<std::size_t>& members,
                                                              std::size_t timeVar, bool seaglider) {
  // Table rules first, by their order.
  std::map<std::size_t, const VarRule*> ruleOf;
  std::set<std::string> taken;
  const auto rules = seaglider ? std::span<const VarRule>(kSeagliderRules) : std::span<const VarRule>(kTrajectoryRules);
  for (const VarRule& r : rules) {
    auto it = byName.find(std::string(r.variable));
    if (it == byName.end() || taken.count(std::string(r.channel))) continue;
    if (std::find(members.begin(), members.end(), it->second) == members.end()) continue;
    ruleOf[it->second] = &r;
    taken.insert(std::string(r.channel));
  }
  // Seaglider files name their sensors; a CF standard name there is shared by
  // the vehicle's, the CT sail's and the ADCP's depth or pressure, which
  // would all claim one channel. Their own names keep them apart.
  std::map<std::size_t, std::string> standardOf;
  for (std::size_t k : members) {
    if (seaglider) break;
    if (ruleOf.count(k) || k == timeVar) continue;
    for (const auto& [sn, ch] : kStandardNames)
      if (vars[k].standard_name == sn && !taken.count(std::string(ch))) {
        standardOf[k] = std::string(ch);
        taken.insert(std::string(ch));
        break;
      }
  }
  std::vector<std::pair<std::size_t, ChannelName>> out;
  for (std::size_t k : members) {
    const NcVariable& v = vars[k];
    if (k == timeVar) continue;
    const std::string lname = v.name.size() > 3 ? v.name.substr(v.name.size() - 3) : "";
    if (lname == "_qc" || lname == "_QC") continue;  // applied to their variable
    ChannelName c;
    if (auto r = ruleOf.find(k); r != ruleOf.end()) {
      c.name = std::string(r->second->channel);
      c.scale = r->second->scale;
      c.to_unit = std::string(r->second->to_unit);
      c.force_unit = std::string(r->second->force_unit);
    } else if (auto s = standardOf.find(k); s != standardOf.end()) {
      c.name = s->second;
    } else {
      c.name = safeChannelName(v.name);
      if (taken.count(c.name) || canonicalUnitFor(c.name).size()) c.name = "nc_" + c.name;
    }
    taken.insert(c.name);
    out.emplace_back(k, std::move(c));
  }
  return out;
}

std::string missingChannels(const std::set<std::string>& found) {
  std::string missing;
  for (auto ch : kExpected)
    if (!found.count(std::string(ch))) missing += (missing.empty() ? "" : ", ") + std::string(ch);
  return missing;
}

}  // namespace auv::detail
