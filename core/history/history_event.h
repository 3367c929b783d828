#pragma once
// One entry of a configuration's history, any kind, for time-ordered views
// and exports. Ties at the same second are ordered by kind in the order a
// ballasting cycle happens (weigh, water, mission, analysis, model, advice,
// install).
#include <nlohmann/json.hpp>
#include <variant>

#include "history/records.h"

namespace auv {

enum class EventKind { kWeighing, kWater, kMission, kAnalysis, kModelTerms, kRecommendation, kInstalled };
const char* toString(EventKind k);  // "weighing", "water", "mission", ...

struct HistoryEvent {
  TimePoint at{};
  EventKind kind = EventKind::kWeighing;
  std::variant<Weighing, WaterCondition, Mission, AnalysisResult, ModelTerms, Recommendation, InstalledState>
      record;
  RecordId id() const;
};

// The state a technician needs before the next mission (thesis pre-mission mode).
struct ConfigurationState {
  Configuration configuration;
  std::optional<InstalledState> installed;       // latest installed pieces per point
  std::optional<Mission> last_mission;
  std::optional<AnalysisResult> last_analysis;   // of the last mission if it has one
  std::optional<WaterCondition> last_temperature;  // latest record with a temperature
  std::optional<std::chrono::seconds> temperature_age;
  bool temperature_stale = true;  // no temperature at all counts as stale
};

struct ConfigurationSummary {
  Configuration configuration;
  TimePoint last_activity{};  // latest record of any kind, or creation
};

nlohmann::json toJson(const Configuration& c);
nlohmann::json toJson(const Weighing& r);
nlohmann::json toJson(const WaterCondition& r);
nlohmann::json toJson(const Mission& r);
nlohmann::json toJson(const AnalysisResult& r);
nlohmann::json toJson(const ModelTerms& r);
nlohmann::json toJson(const Recommendation& r);
nlohmann::json toJson(const InstalledState& r);
nlohmann::json toJson(const HistoryEvent& e);  // {"at","kind","id","record"}

nlohmann::json pointsToJson(const std::vector<InstalledPoint>& points);
// Reads what pointsToJson wrote; `where` names the source in errors.
std::vector<InstalledPoint> pointsFromJson(const nlohmann::json& j, const std::string& where);

}  // namespace auv
