#include "workflow/history_calibration.h"

#include "analysis/steady_segment_json.h"
#include "common/input_error.h"
#include "history/store.h"
#include "workflow/plan_inputs_from_history.h"

namespace auv {

std::vector<analysis::HistoryMission> historyCalibrationMissions(HistoryStore& store, const std::string& config_id,
                                                                 const VehicleProfile& v, TimePoint now,
                                                                 const std::string& current_log) {
  std::vector<analysis::HistoryMission> out;
  if (v.kind != "auv" || !store.configuration(config_id)) return out;
  const auto a = store.latestAnalysis(config_id, now);
  if (!a) return out;
  const nlohmann::json& r = a->result;
  if (!r.contains("details") || !r["details"].is_object()) return out;
  if (r.contains("log") && r["log"].is_string() && r["log"].get<std::string>() == current_log) return out;
  const nlohmann::json& d = r["details"];
  if (!d.contains("installed_kg") || !d.contains("auv_estimate") || !d["auv_estimate"].contains("steady_segments"))
    return out;
  analysis::HistoryMission m;
  const std::string where = "history analysis #" + std::to_string(a->id);
  for (const auto& kg : d["installed_kg"]) {
    if (!kg.is_number()) return out;
    m.installed_kg.push_back(kg.get<double>());
  }
  if (m.installed_kg.size() != v.points.size()) return out;  // another layout: no known change
  m.segments = analysis::steadySegmentsFromJson(d["auv_estimate"]["steady_segments"], where + " steady_segments");
  // The accepted sensor biases that analysis took out of its segments (none: an older analysis, or none accepted).
  if (d["auv_estimate"].contains("attitude_bias_removed_deg")) {
    const nlohmann::json& b = d["auv_estimate"]["attitude_bias_removed_deg"];
    for (auto [key, field] : {std::pair{"pitch", &m.pitch_bias_removed_deg}, {"roll", &m.roll_bias_removed_deg}}) {
      if (!b.is_object() || !b.contains(key) || !b[key].is_number())
        throw InputError(where + " attitude_bias_removed_deg." + key, "is missing or not a number",
                         "analyse that mission again with 'auvballast model-check --config ID'");
      *field = b[key].get<double>();
    }
  }
  if (!m.segments.empty()) out.push_back(std::move(m));
  return out;
}

void addConfigurationHistory(HistoryStore& store, const std::string& config_id, const VehicleProfile& v, TimePoint now,
                             analysis::AnalysisOptions& a) {
  const HistoryPlanInputs h = planInputsFromHistory(store, config_id, v, now);
  if (!h.configuration_known)
    throw InputError("config", "'" + config_id + "' is not in the history '" + store.path() + "'",
                     "record the configuration first (first-mission or the wizard)");
  if (a.installed_kg.empty() && h.installed) a.installed_kg = installedKg(*h.installed, v, config_id);
  // The configuration's roll test, as the wizard uses it (CG y becomes identifiable).
  const std::optional<Configuration> c = store.configuration(config_id);
  if (!a.bg_m && v.kind == "auv" && c && c->bg_mm) a.bg_m = *c->bg_mm / 1000.0;
  // Its dock level check narrows the prior on the pitch sensor's bias.
  if (v.kind == "auv" && c && c->pitch_level_check_deg) a.pitch_alignment_sigma_deg = *c->pitch_level_check_deg;
  a.history = historyCalibrationMissions(store, config_id, v, now, a.log_name);
}

}  // namespace auv
