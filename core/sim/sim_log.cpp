#include "sim/sim_log.h"

#include <charconv>
#include <cmath>

#include "common/units.h"
#include "missionlog/interchange_csv.h"

namespace auv::sim {

std::string formatNumber(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

namespace {

// Adds `name [unit]` = scale * values, unless every value is NaN (a channel
// the simulation did not produce, e.g. heading_cmd without heading hold).
void addChannel(MissionLog& log, const char* name, const char* unit, const std::vector<double>& values,
                double scale = 1.0) {
  bool any = false;
  for (double v : values) any = any || !std::isnan(v);
  if (!any) return;
  LogChannel& c = log.addChannel(name, unit);
  for (std::size_t i = 0; i < values.size(); ++i) c.values[i] = scale * values[i];
}

}  // namespace

MetadataEntry latitudeMetadata(double latitude_deg) { return {"latitude", formatNumber(latitude_deg)}; }

MissionLog toMissionLog(const SimTrace& tr, const SimLogInfo& info) {
  MissionLog log;
  log.metadata.push_back({"vehicle", info.vehicle});
  log.metadata.push_back({"source", "auvballast simulate"});
  log.metadata.push_back({"mode", info.mode});
  if (!info.input.empty()) log.metadata.push_back({info.mode == "replay" ? "replay_of" : "plan", info.input});
  log.metadata.push_back({"seed", std::to_string(info.seed)});
  const SimTrace::Truth& t = tr.truth;
  double mean_nb = 0.0;
  for (double nb : tr.net_buoyancy_n) mean_nb += nb;
  if (tr.size() > 0) mean_nb /= static_cast<double>(tr.size());
  log.metadata.push_back({"truth_net_buoyancy_kg", formatNumber(t.net_buoyancy_start_n / units::g0)});
  log.metadata.push_back({"truth_net_buoyancy_mean_kg", formatNumber(mean_nb / units::g0)});
  log.metadata.push_back({"truth_cg_x_mm", formatNumber(units::mToMm(t.cg_x_m))});
  log.metadata.push_back({"truth_cg_y_mm", formatNumber(units::mToMm(t.cg_y_m))});
  log.metadata.push_back({"truth_cg_z_mm", formatNumber(units::mToMm(t.cg_z_m))});
  log.metadata.push_back({"truth_frame", "CG relative to CB, body axes x fwd, y stbd, z down"});
  log.metadata.push_back({"truth_mass_kg", formatNumber(t.mass_kg)});
  log.metadata.push_back({"truth_hull_volume_m3", formatNumber(t.hull_volume_m3)});
  if (!std::isnan(t.net_buoyancy_pump0_mean_n)) {
    log.metadata.push_back({"truth_net_buoyancy_pump0_mean_kg", formatNumber(t.net_buoyancy_pump0_mean_n / units::g0)});
  }
  if (!info.installed_kg.empty()) {
    std::string kg;
    for (double m : info.installed_kg) {
      if (!kg.empty()) kg += ',';
      kg += formatNumber(m);
    }
    log.metadata.push_back({"installed_kg", kg});
  }
  for (const MetadataEntry& e : info.extra) log.metadata.push_back(e);

  log.time = tr.time_s;
  const double deg = units::radToDeg(1.0);
  addChannel(log, "depth", "m", tr.depth_m);
  addChannel(log, "depth_cmd", "m", tr.depth_cmd_m);
  addChannel(log, "pitch", "deg", tr.pitch_rad, deg);
  addChannel(log, "pitch_cmd", "deg", tr.pitch_cmd_rad, deg);
  addChannel(log, "roll", "deg", tr.roll_rad, deg);
  addChannel(log, "heading", "deg", tr.heading_rad, deg);
  addChannel(log, "heading_cmd", "deg", tr.heading_cmd_rad, deg);
  // A glider measures no speed through water: its simulated speed stays out.
  const bool glider = !tr.pump_volume_m3.empty();
  if (!glider) addChannel(log, "speed", "m/s", tr.speed_mps);
  addChannel(log, "prop_rpm", "rpm", tr.prop_rpm);
  addChannel(log, "elevator", "deg", tr.elevator_rad, deg);
  addChannel(log, "rudder", "deg", tr.rudder_rad, deg);
  if (info.thruster_count > 0) {
    addChannel(log, "thruster_front_rpm", "rpm", tr.thruster_front_rpm);
    addChannel(log, "thruster_aft_rpm", "rpm", tr.thruster_aft_rpm);
  }
  addChannel(log, "pump_volume", "cm3", tr.pump_volume_m3, 1e6);
  addChannel(log, "battery_position", "mm", tr.battery_position_m, 1e3);
  addChannel(log, "roll_mass", "deg", tr.roll_mass_rad, deg);
  addChannel(log, "temperature", "degC", tr.temperature_degC);
  addChannel(log, "salinity", "PSU", tr.salinity_psu);
  addChannel(log, "pressure", "dbar", tr.pressure_dbar);
  addChannel(log, "power", "W", tr.power_w);
  return log;
}

void writeSimulatedLog(const SimTrace& trace, const SimLogInfo& info, const std::filesystem::path& path) {
  writeInterchangeCsv(toMissionLog(trace, info), path);
}

}  // namespace auv::sim
