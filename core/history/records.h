#pragma once
// The typed records of the ballasting history, one struct per table. A record
// belongs to one configuration (thesis §5.5.1: one vehicle, one payload set,
// one water of operation); the store takes the configuration ID separately.
// Free-form results (weighing inputs, mission summaries, analyses,
// recommendations) are JSON so that their producers can evolve without a
// schema migration; everything the history itself reasons about is typed.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "history/database.h"
#include "history/timestamp.h"

namespace auv {

struct Vehicle {
  RecordId id = 0;
  std::string key;   // profile id, e.g. "hugin1000"
  std::string name;  // as shown to people, e.g. "HUGIN1000"
};

struct Configuration {
  RecordId id = 0;
  std::string config_id;  // thesis xx-xx-xx
  std::string vehicle_key;
  std::string vehicle_name;
  std::string payload_note;
  std::string area;        // area of operation, e.g. "Horten"
  std::string water_type;  // e.g. "coastal", "fjord", "open ocean"
  TimePoint created_at{};
  // CG below CB from an inclining or roll test (what makes CG y and roll
  // identifiable from a log); unset = not measured.
  std::optional<double> bg_mm;
  // How closely its pitch sensor was checked level on the dock, deg (the
  // analysis's prior on the sensor's bias); unset = not checked.
  std::optional<double> pitch_level_check_deg;
};

enum class WeighingMethod { kCrane, kTank };
const char* toString(WeighingMethod m);
WeighingMethod weighingMethodFromString(const std::string& s);  // InputError if unknown

struct Weighing {
  RecordId id = 0;
  TimePoint at{};
  WeighingMethod method = WeighingMethod::kCrane;
  nlohmann::json inputs = nlohmann::json::object();   // raw readings as entered
  nlohmann::json results = nlohmann::json::object();  // mass, CG, ...
};

struct WaterCondition {
  RecordId id = 0;
  TimePoint measured_at{};
  std::optional<double> temperature_degC;
  std::optional<double> salinity_psu;
  std::optional<double> depth_m;
  std::optional<double> density_kg_m3;
  std::string source;  // "operator", "ctd", "mission", "ballasting-file", ...
};

struct Mission {
  RecordId id = 0;
  TimePoint imported_at{};
  std::string file_path;
  std::string sha256;  // of the file content, 64 lower-case hex digits
  nlohmann::json summary = nlohmann::json::object();
};

struct AnalysisResult {
  RecordId id = 0;
  TimePoint at{};
  std::optional<RecordId> mission_id;
  nlohmann::json result = nlohmann::json::object();
};

// The configuration's vehicle model after a model check: the terms the
// technician accepted and the vehicle profile with them written in
// (discrepancy/profile_update.h), which the simulator, the analysis and the
// planner use from then on. `model` = {"log", "accepted": [...], "profile": {...}}.
struct ModelTerms {
  RecordId id = 0;
  TimePoint at{};
  std::optional<RecordId> analysis_id;
  nlohmann::json model = nlohmann::json::object();
};

struct Recommendation {
  RecordId id = 0;
  TimePoint at{};
  std::optional<RecordId> analysis_id;
  std::string policy;  // "exact", "half", "classic", ...
  nlohmann::json recommendation = nlohmann::json::object();
  bool accepted = false;
};

struct InstalledPoint {
  std::string name;  // adjustment point, e.g. "fore_starboard"
  double mass_kg = 0.0;
  std::vector<double> pieces_kg;  // kit pieces making up mass_kg; empty if not known
};

// What the technician actually installed, which may differ from the recommendation.
struct InstalledState {
  RecordId id = 0;
  TimePoint installed_at{};
  std::optional<RecordId> recommendation_id;
  std::vector<InstalledPoint> points;
  std::optional<double> total_mass_kg;  // vehicle mass with these pieces, if weighed/known
  std::string note;
};

}  // namespace auv
