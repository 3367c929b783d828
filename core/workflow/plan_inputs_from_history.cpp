#include "workflow/plan_inputs_from_history.h"

#include <algorithm>

#include "common/input_error.h"
#include "discrepancy/profile_update.h"
#include "history/store.h"

namespace auv {

std::vector<double> installedKg(const InstalledState& st, const VehicleProfile& v, const std::string& config_id) {
  std::vector<double> kg(v.points.size(), 0.0);
  for (const InstalledPoint& p : st.points) {
    const auto it = std::find_if(v.points.begin(), v.points.end(), [&](const AdjustmentPoint& a) { return a.name == p.name; });
    if (it == v.points.end()) {
      throw InputError("installed", "the history of configuration " + config_id + " names point '" + p.name +
                                        "', which vehicle " + v.id + " does not have",
                       "give the installed pieces for this vehicle (--installed in the CLI)");
    }
    kg[static_cast<std::size_t>(it - v.points.begin())] = p.mass_kg;
  }
  return kg;
}

HistoryPlanInputs planInputsFromHistory(HistoryStore& store, const std::string& config_id, const VehicleProfile& base,
                                        TimePoint now) {
  HistoryPlanInputs in;
  in.vehicle = base;
  const std::optional<Configuration> config = store.configuration(config_id);
  if (!config) return in;
  in.configuration_known = true;
  if (config->vehicle_key != base.id) {
    throw InputError("vehicle", "configuration " + config_id + " is a " + config->vehicle_name + " in the history",
                     "use --vehicle " + config->vehicle_key + " or another configuration ID");
  }
  // The configuration's vehicle model (terms accepted and constants
  // calibrated in model checks): its hull law sets the buoyancy at other
  // depths, its hydrodynamics the flight the plan predicts.
  if (const auto m = store.latestModelTerms(config_id, now); m && m->model.contains("profile")) {
    in.vehicle = discrepancy::vehicleFromStoredProfile(m->model["profile"], base, "history model of " + config_id);
    in.model_terms = m->model.value("accepted", nlohmann::json::array()).size();
    const nlohmann::json& mc = m->model["profile"].value("model_check", nlohmann::json::object());
    in.model_calibrated = mc.value("calibrated", nlohmann::json::array()).size();
    in.model_from_history = true;
  }
  in.installed = store.latestInstalled(config_id, now);
  if (in.installed) in.total_mass_kg = in.installed->total_mass_kg;
  in.analysis = store.latestAnalysis(config_id, now);
  if (const auto w = store.latestWater(config_id, now, true); w && w->temperature_degC) {
    in.measured_water = MeasuredWater{*w->temperature_degC, w->salinity_psu.value_or(35.0)};
    in.measured_water_at = w->measured_at;
  }
  return in;
}

}  // namespace auv
