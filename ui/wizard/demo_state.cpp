#include "wizard/demo_state.h"


#include "common/units.h"
#include "firstmission/crane_weighing_file.h"
#include "missionlog/interchange_csv.h"
#include "sim/mission_plan.h"
#include "sim/simulator.h"
#include "vehicle/vehicle_catalog.h"
#include "wizard/history_save.h"
#include "weighing/tank_weighing_file.h"

namespace auv::ui {

WizardState makeEmptyState(const std::string& resource_dir) {
  WizardState s;
  s.resource_dir = resource_dir;
  s.vehicles_dir = resource_dir + "/vehicles";
  s.crane.water = {10.0, 35.0, 0.0, 60.0};
  s.tank.readings.tank = {kFreshTankDensityKgm3, 18.0};
  s.tank.readings.target = {1025.0, 10.0};
  return s;
}

WizardState makeDemoState(const std::string& resource_dir) {
  WizardState s = makeEmptyState(resource_dir);
  const CraneWeighingFile f = loadCraneWeighingFile(resource_dir + "/examples/hugin1000_first_mission.json");
  s.vehicle = VehicleCatalog(s.vehicles_dir).load(f.vehicle);
  s.crane = f.input;
  s.configuration_id = "01-02-03";
  s.payload_note = "Demo: thesis whole-system test vehicle";
  s.area = "Horten";
  s.water_type = "fjord";
  return s;
}

WizardState makeSlocumDemoState(const std::string& resource_dir) {
  WizardState s = makeEmptyState(resource_dir);
  s.tank = loadTankWeighing(resource_dir + "/examples/slocum_tank_weighing.json");
  s.vehicle = VehicleCatalog(s.vehicles_dir).load(s.tank.vehicle.empty() ? "slocum_g2" : s.tank.vehicle);
  // The file says "fresh" and the loader keeps only the density; fresh tank
  // water is what the loader accepts without a stated density (<= 1010).
  s.tank_water_salt = s.tank.readings.tank.density_kgm3 > 1010.0;
  s.configuration_id = "49-1-1";
  s.payload_note = "Demo: Baird 2007 App. B session, glider 49";
  s.area = "Bedford Basin";
  s.water_type = "coastal";
  return s;
}

std::size_t writeDemoSurveyLog(const std::string& resource_dir, const std::string& log_path) {
  const sim::MissionPlan plan = sim::loadMissionPlan(resource_dir + "/examples/hugin1000_survey.plan.json");
  const VehicleProfile v = VehicleCatalog(resource_dir + "/vehicles").load(plan.vehicle);
  const sim::SimVehicle sv = sim::loadSimVehicle(v, resource_dir);
  const sim::SimTrace tr = sim::simulate(sv.model, sv.autopilot, plan.water, plan.scenario, plan.options);
  MissionLog log;
  log.setMetadata("vehicle", plan.vehicle);
  log.setMetadata("mission", "demo survey simulated by auvballast (core/sim)");
  log.setMetadata("start", "2026-05-14T08:12:00Z");
  log.setMetadata("configuration", "01-02-03");
  log.time = tr.time_s;
  auto add = [&](const char* name, const char* unit, const std::vector<double>& values, double scale) {
    LogChannel& c = log.addChannel(name, unit);
    for (std::size_t i = 0; i < values.size() && i < c.values.size(); ++i) c.values[i] = values[i] * scale;
  };
  const double deg = units::radToDeg(1.0);
  add("depth", "m", tr.depth_m, 1.0);
  add("depth_cmd", "m", tr.depth_cmd_m, 1.0);
  add("pitch", "deg", tr.pitch_rad, deg);
  add("pitch_cmd", "deg", tr.pitch_cmd_rad, deg);
  add("roll", "deg", tr.roll_rad, deg);
  add("speed", "m/s", tr.speed_mps, 1.0);
  add("prop_rpm", "rpm", tr.prop_rpm, 1.0);
  add("elevator", "deg", tr.elevator_rad, deg);  // the analysis needs it for net buoyancy and CG x
  add("temperature", "degC", tr.temperature_degC, 1.0);
  add("salinity", "PSU", tr.salinity_psu, 1.0);
  writeInterchangeCsv(log, log_path);
  return log.rowCount();
}

WizardState makePostMissionDemoState(const std::string& resource_dir, const std::string& log_path) {
  WizardState s = makeDemoState(resource_dir);
  s.mode = SessionMode::kPostMission;
  s.configuration_in_history = true;
  writeDemoSurveyLog(resource_dir, log_path);
  s.log_file = log_path;
  return s;
}

void seedDemoHistory(HistoryStore& store, const std::string& resource_dir, TimePoint when) {
  WizardState s = makeDemoState(resource_dir);
  s.report = craneFirstMission(*s.vehicle, s.crane);
  saveFirstMissionToHistory(store, s, when);
  InstalledState installed;
  installed.installed_at = when;
  installed.note = "as weighed (demo)";
  for (std::size_t i = 0; i < s.vehicle->points.size() && i < s.crane.installed_kg.size(); ++i) {
    installed.points.push_back({s.vehicle->points[i].name, s.crane.installed_kg[i], {}});
  }
  store.addInstalledState(s.configuration_id, installed);
}

}  // namespace auv::ui
