// The queries of HistoryStore. Column lists are kept next to their readers so
// that a SELECT and the code reading its columns cannot drift apart.
#include <algorithm>

#include "common/input_error.h"
#include "history/staleness.h"
#include "history/store.h"

namespace auv {
namespace {

nlohmann::json parseStored(const std::string& text, const std::string& what) {
  // The CHECK(json_valid) constraint makes a failure here mean damage.
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("history database", "stored " + what + " is not valid JSON: " + e.what(),
                     "restore the file from a backup");
  }
}

const char* kConfigSelect = "c.id, c.config_id, v.key, v.name, c.payload_note, c.area, c.water_type, c.created_at, ";
const char* kConfigFrom = " FROM configurations c JOIN vehicles v ON v.id = c.vehicle_id";
constexpr int kConfigColumnCount = 10;  // what readConfiguration reads: columns 0..9
Configuration readConfiguration(Statement& st) {
  Configuration c;
  c.id = st.integer(0);
  c.config_id = st.text(1);
  c.vehicle_key = st.text(2);
  c.vehicle_name = st.text(3);
  c.payload_note = st.text(4);
  c.area = st.text(5);
  c.water_type = st.text(6);
  c.created_at = parseIsoUtc(st.text(7), "configurations.created_at");
  c.bg_mm = st.optReal(8);
  c.pitch_level_check_deg = st.optReal(9);
  return c;
}

const char* kWeighingCols = "id, at, method, inputs_json, results_json FROM weighings";
Weighing readWeighing(Statement& st) {
  Weighing w;
  w.id = st.integer(0);
  w.at = parseIsoUtc(st.text(1), "weighings.at");
  w.method = weighingMethodFromString(st.text(2));
  w.inputs = parseStored(st.text(3), "weighing inputs");
  w.results = parseStored(st.text(4), "weighing results");
  return w;
}

const char* kWaterCols =
    "id, measured_at, temperature_degc, salinity_psu, depth_m, density_kg_m3, source "
    "FROM water_conditions";
WaterCondition readWater(Statement& st) {
  WaterCondition w;
  w.id = st.integer(0);
  w.measured_at = parseIsoUtc(st.text(1), "water_conditions.measured_at");
  w.temperature_degC = st.optReal(2);
  w.salinity_psu = st.optReal(3);
  w.depth_m = st.optReal(4);
  w.density_kg_m3 = st.optReal(5);
  w.source = st.text(6);
  return w;
}

const char* kMissionCols = "id, imported_at, file_path, sha256, summary_json FROM missions";
Mission readMission(Statement& st) {
  Mission m;
  m.id = st.integer(0);
  m.imported_at = parseIsoUtc(st.text(1), "missions.imported_at");
  m.file_path = st.text(2);
  m.sha256 = st.text(3);
  m.summary = parseStored(st.text(4), "mission summary");
  return m;
}

const char* kAnalysisCols = "id, at, mission_id, result_json FROM analysis_results";
AnalysisResult readAnalysis(Statement& st) {
  AnalysisResult a;
  a.id = st.integer(0);
  a.at = parseIsoUtc(st.text(1), "analysis_results.at");
  a.mission_id = st.optInteger(2);
  a.result = parseStored(st.text(3), "analysis result");
  return a;
}

const char* kModelTermsCols = "id, at, analysis_id, model_json FROM model_terms";
ModelTerms readModelTerms(Statement& st) {
  ModelTerms m;
  m.id = st.integer(0);
  m.at = parseIsoUtc(st.text(1), "model_terms.at");
  m.analysis_id = st.optInteger(2);
  m.model = parseStored(st.text(3), "model terms");
  return m;
}

const char* kRecommendationCols =
    "id, at, analysis_id, policy, recommendation_json, accepted FROM recommendations";
Recommendation readRecommendation(Statement& st) {
  Recommendation r;
  r.id = st.integer(0);
  r.at = parseIsoUtc(st.text(1), "recommendations.at");
  r.analysis_id = st.optInteger(2);
  r.policy = st.text(3);
  r.recommendation = parseStored(st.text(4), "recommendation");
  r.accepted = st.integer(5) != 0;
  return r;
}

const char* kInstalledCols =
    "id, installed_at, recommendation_id, pieces_json, total_mass_kg, note FROM installed_states";
InstalledState readInstalled(Statement& st) {
  InstalledState s;
  s.id = st.integer(0);
  s.installed_at = parseIsoUtc(st.text(1), "installed_states.installed_at");
  s.recommendation_id = st.optInteger(2);
  s.points = pointsFromJson(parseStored(st.text(3), "installed pieces"), "installed_states");
  s.total_mass_kg = st.optReal(4);
  s.note = st.text(5);
  return s;
}

template <class Reader>
auto latest(Database& db, const std::string& cols, const std::string& time_col,
            const std::string& extra, RecordId config, TimePoint t, Reader read)
    -> std::optional<decltype(read(std::declval<Statement&>()))> {
  auto st = db.prepare("SELECT " + cols + " WHERE configuration_id = ?1 AND " + time_col +
                       " <= ?2" + extra + " ORDER BY " + time_col + " DESC, id DESC LIMIT 1");
  st.bind(1, config).bind(2, toIsoUtc(t));
  if (!st.step()) return std::nullopt;
  return read(st);
}

std::string likePattern(const std::string& text) {
  std::string p = "%";
  for (char c : text) {
    if (c == '%' || c == '_' || c == '\\') p += '\\';
    p += c;
  }
  return p + "%";
}
}  // namespace

std::string HistoryStore::configColumns() const {
  return std::string(kConfigSelect) + (has_bg_column_ ? "c.bg_mm" : "NULL") +
         (has_level_check_column_ ? ", c.pitch_level_check_deg" : ", NULL") + kConfigFrom;
}

std::optional<Configuration> HistoryStore::configuration(const std::string& config_id) {
  auto st = db_->prepare(std::string("SELECT ") + configColumns() + " WHERE c.config_id = ?1");
  st.bind(1, config_id);
  if (!st.step()) return std::nullopt;
  return readConfiguration(st);
}

std::optional<WaterCondition> HistoryStore::latestWater(const std::string& config_id, TimePoint t,
                                                        bool with_temperature) {
  return latest(*db_, kWaterCols, "measured_at",
                with_temperature ? " AND temperature_degc IS NOT NULL" : "", configRow(config_id),
                t, readWater);
}

std::optional<AnalysisResult> HistoryStore::latestAnalysis(const std::string& config_id,
                                                           TimePoint t) {
  return latest(*db_, kAnalysisCols, "at", "", configRow(config_id), t, readAnalysis);
}

std::optional<ModelTerms> HistoryStore::latestModelTerms(const std::string& config_id, TimePoint t) {
  return latest(*db_, kModelTermsCols, "at", "", configRow(config_id), t, readModelTerms);
}

std::optional<InstalledState> HistoryStore::latestInstalled(const std::string& config_id,
                                                            TimePoint t) {
  return latest(*db_, kInstalledCols, "installed_at", "", configRow(config_id), t, readInstalled);
}

std::optional<Mission> HistoryStore::missionBySha256(const std::string& config_id,
                                                     const std::string& sha) {
  auto st = db_->prepare(std::string("SELECT ") + kMissionCols +
                         " WHERE configuration_id = ?1 AND sha256 = ?2");
  st.bind(1, configRow(config_id)).bind(2, sha);
  if (!st.step()) return std::nullopt;
  return readMission(st);
}

std::optional<ConfigurationState> HistoryStore::lastState(const std::string& config_id,
                                                          TimePoint now) {
  auto config = configuration(config_id);
  if (!config) return std::nullopt;
  // "Last" means last saved in time, including records dated after `now`
  // (a clock set wrong must not hide them).
  const TimePoint end = makeUtc(9999, 12, 31, 23, 59, 59);
  ConfigurationState s;
  s.configuration = *config;
  s.installed = latestInstalled(config_id, end);
  s.last_mission = latest(*db_, kMissionCols, "imported_at", "", config->id, end, readMission);
  if (s.last_mission) {
    auto st = db_->prepare(std::string("SELECT ") + kAnalysisCols +
                           " WHERE mission_id = ?1 ORDER BY at DESC, id DESC LIMIT 1");
    st.bind(1, s.last_mission->id);
    if (st.step()) s.last_analysis = readAnalysis(st);
  }
  if (!s.last_analysis) s.last_analysis = latestAnalysis(config_id, end);
  s.last_temperature = latestWater(config_id, end, true);
  if (s.last_temperature) {
    s.temperature_age = now - s.last_temperature->measured_at;
    s.temperature_stale = temperatureIsStale(s.last_temperature->measured_at, now);
  }
  return s;
}

std::vector<HistoryEvent> HistoryStore::history(const std::string& config_id) {
  const RecordId config = configRow(config_id);
  std::vector<HistoryEvent> events;
  auto collect = [&](const char* cols, EventKind kind, auto read, auto time_of) {
    auto st = db_->prepare(std::string("SELECT ") + cols + " WHERE configuration_id = ?1");
    st.bind(1, config);
    while (st.step()) {
      auto rec = read(st);
      events.push_back(HistoryEvent{time_of(rec), kind, rec});
    }
  };
  collect(kWeighingCols, EventKind::kWeighing, readWeighing, [](const Weighing& r) { return r.at; });
  collect(kWaterCols, EventKind::kWater, readWater,
          [](const WaterCondition& r) { return r.measured_at; });
  collect(kMissionCols, EventKind::kMission, readMission,
          [](const Mission& r) { return r.imported_at; });
  collect(kAnalysisCols, EventKind::kAnalysis, readAnalysis,
          [](const AnalysisResult& r) { return r.at; });
  collect(kModelTermsCols, EventKind::kModelTerms, readModelTerms, [](const ModelTerms& r) { return r.at; });
  collect(kRecommendationCols, EventKind::kRecommendation, readRecommendation,
          [](const Recommendation& r) { return r.at; });
  collect(kInstalledCols, EventKind::kInstalled, readInstalled,
          [](const InstalledState& r) { return r.installed_at; });
  std::stable_sort(events.begin(), events.end(), [](const HistoryEvent& a, const HistoryEvent& b) {
    if (a.at != b.at) return a.at < b.at;
    if (a.kind != b.kind) return a.kind < b.kind;
    return a.id() < b.id();
  });
  return events;
}

std::vector<ConfigurationSummary> HistoryStore::recentConfigurations(std::size_t limit) {
  // ISO-8601 text compares in time order, so MAX over the text is the latest;
  // multi-argument max() is NULL if any argument is, hence the COALESCEs.
  const std::string cols = configColumns();
  const std::string select = cols.substr(0, cols.find(" FROM configurations"));
  auto st = db_->prepare("SELECT " + select + R"sql(,
      max(c.created_at,
          coalesce((SELECT max(at) FROM weighings WHERE configuration_id = c.id), ''),
          coalesce((SELECT max(measured_at) FROM water_conditions WHERE configuration_id = c.id), ''),
          coalesce((SELECT max(imported_at) FROM missions WHERE configuration_id = c.id), ''),
          coalesce((SELECT max(at) FROM analysis_results WHERE configuration_id = c.id), ''),
          coalesce((SELECT max(at) FROM recommendations WHERE configuration_id = c.id), ''),
          coalesce((SELECT max(installed_at) FROM installed_states WHERE configuration_id = c.id), ''))
      AS last_activity)sql" + std::string(kConfigFrom) + R"sql(
    ORDER BY last_activity DESC, c.id DESC LIMIT ?1)sql");
  st.bind(1, std::int64_t(std::min<std::size_t>(limit, 1u << 30)));
  std::vector<ConfigurationSummary> out;
  while (st.step()) {
    ConfigurationSummary s;
    s.configuration = readConfiguration(st);
    s.last_activity = parseIsoUtc(st.text(kConfigColumnCount), "last activity");
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Configuration> HistoryStore::search(const std::string& text) {
  // LIKE is case-insensitive for ASCII, which covers IDs and place names typed
  // on a workshop keyboard; the wildcards in the user's text are escaped.
  auto st = db_->prepare(std::string("SELECT ") + configColumns() +
                         " WHERE c.config_id LIKE ?1 ESCAPE '\\' OR c.payload_note LIKE ?1 "
                         "ESCAPE '\\' OR c.area LIKE ?1 ESCAPE '\\' OR c.water_type LIKE ?1 "
                         "ESCAPE '\\' OR v.key LIKE ?1 ESCAPE '\\' OR v.name LIKE ?1 ESCAPE '\\' "
                         "ORDER BY c.config_id");
  st.bind(1, likePattern(text));
  std::vector<Configuration> out;
  while (st.step()) out.push_back(readConfiguration(st));
  return out;
}

}  // namespace auv
