// JSON views of the history records, used by the JSON/CSV exports and by
// installed_states.pieces_json. Absent optionals are written as null so a
// reader sees "not known" rather than a missing key.
#include <cmath>

#include "common/input_error.h"
#include "history/history_event.h"

namespace auv {
namespace {
template <class T>
nlohmann::json opt(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}
}  // namespace

const char* toString(EventKind k) {
  switch (k) {
    case EventKind::kWeighing: return "weighing";
    case EventKind::kWater: return "water";
    case EventKind::kMission: return "mission";
    case EventKind::kAnalysis: return "analysis";
    case EventKind::kModelTerms: return "model_terms";
    case EventKind::kRecommendation: return "recommendation";
    case EventKind::kInstalled: return "installed";
  }
  return "?";
}

RecordId HistoryEvent::id() const {
  return std::visit([](const auto& r) { return r.id; }, record);
}

nlohmann::json toJson(const Configuration& c) {
  nlohmann::json j = {{"config_id", c.config_id},     {"vehicle", c.vehicle_key},
                      {"vehicle_name", c.vehicle_name}, {"payload_note", c.payload_note},
                      {"area", c.area},                 {"water_type", c.water_type},
                      {"created_at", toIsoUtc(c.created_at)}};
  if (c.bg_mm) j["bg_mm"] = *c.bg_mm;  // absent = not measured
  if (c.pitch_level_check_deg) j["pitch_level_check_deg"] = *c.pitch_level_check_deg;  // absent = not checked
  return j;
}

nlohmann::json toJson(const Weighing& r) {
  return {{"id", r.id}, {"at", toIsoUtc(r.at)}, {"method", toString(r.method)},
          {"inputs", r.inputs}, {"results", r.results}};
}

nlohmann::json toJson(const WaterCondition& r) {
  return {{"id", r.id},
          {"measured_at", toIsoUtc(r.measured_at)},
          {"temperature_degC", opt(r.temperature_degC)},
          {"salinity_psu", opt(r.salinity_psu)},
          {"depth_m", opt(r.depth_m)},
          {"density_kg_m3", opt(r.density_kg_m3)},
          {"source", r.source}};
}

nlohmann::json toJson(const Mission& r) {
  return {{"id", r.id}, {"imported_at", toIsoUtc(r.imported_at)}, {"file_path", r.file_path},
          {"sha256", r.sha256}, {"summary", r.summary}};
}

nlohmann::json toJson(const AnalysisResult& r) {
  return {{"id", r.id}, {"at", toIsoUtc(r.at)}, {"mission_id", opt(r.mission_id)},
          {"result", r.result}};
}

nlohmann::json toJson(const ModelTerms& r) {
  return {{"id", r.id}, {"at", toIsoUtc(r.at)}, {"analysis_id", opt(r.analysis_id)}, {"model", r.model}};
}

nlohmann::json toJson(const Recommendation& r) {
  return {{"id", r.id},         {"at", toIsoUtc(r.at)},
          {"analysis_id", opt(r.analysis_id)}, {"policy", r.policy},
          {"recommendation", r.recommendation}, {"accepted", r.accepted}};
}

nlohmann::json toJson(const InstalledState& r) {
  return {{"id", r.id},
          {"installed_at", toIsoUtc(r.installed_at)},
          {"recommendation_id", opt(r.recommendation_id)},
          {"points", pointsToJson(r.points)},
          {"total_mass_kg", opt(r.total_mass_kg)},
          {"note", r.note}};
}

nlohmann::json toJson(const HistoryEvent& e) {
  return {{"at", toIsoUtc(e.at)},
          {"kind", toString(e.kind)},
          {"id", e.id()},
          {"record", std::visit([](const auto& r) { return toJson(r); }, e.record)}};
}

nlohmann::json pointsToJson(const std::vector<InstalledPoint>& points) {
  nlohmann::json a = nlohmann::json::array();
  for (const InstalledPoint& p : points)
    a.push_back({{"name", p.name}, {"mass_kg", p.mass_kg}, {"pieces_kg", p.pieces_kg}});
  return a;
}

std::vector<InstalledPoint> pointsFromJson(const nlohmann::json& j, const std::string& where) {
  auto bad = [&](const std::string& problem) {
    throw InputError(where + ".points", problem, "restore the file from a backup");
  };
  if (!j.is_array()) bad("not a JSON array");
  std::vector<InstalledPoint> points;
  for (const auto& e : j) {
    if (!e.is_object() || !e.contains("name") || !e["name"].is_string() ||
        !e.contains("mass_kg") || !e["mass_kg"].is_number())
      bad("point without a name or mass_kg");
    InstalledPoint p;
    p.name = e["name"].get<std::string>();
    p.mass_kg = e["mass_kg"].get<double>();
    if (e.contains("pieces_kg")) {
      if (!e["pieces_kg"].is_array()) bad("pieces_kg is not an array");
      for (const auto& piece : e["pieces_kg"]) {
        if (!piece.is_number()) bad("piece is not a number");
        p.pieces_kg.push_back(piece.get<double>());
      }
    }
    points.push_back(std::move(p));
  }
  return points;
}

}  // namespace auv
