#include "workflow/history_calibration.h"

#include "analysis/steady_segment_json.h"
#include "history/store.h"

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
  if (!m.segments.empty()) out.push_back(std::move(m));
  return out;
}

}  // namespace auv
