// The saves of HistoryStore: validate, then one transaction per save.
#include <cmath>

#include "common/input_error.h"
#include "history/configuration_id.h"
#include "history/sha256.h"
#include "history/store.h"
#include "history/transaction.h"

namespace auv {
namespace {

void requireRange(const std::optional<double>& v, double lo, double hi, const std::string& field,
                  const std::string& unit) {
  if (!v) return;
  if (!std::isfinite(*v) || *v < lo || *v > hi)
    throw InputError(field, "value " + std::to_string(*v) + " is outside " + std::to_string(lo) +
                                ".." + std::to_string(hi) + " " + unit,
                     "enter the measured value in " + unit);
}

void validate(const WaterCondition& w) {
  requireRange(w.temperature_degC, -3.0, 45.0, "water.temperature_degC", "degC");
  requireRange(w.salinity_psu, 0.0, 45.0, "water.salinity_psu", "PSU");
  requireRange(w.depth_m, 0.0, 12000.0, "water.depth_m", "m");
  requireRange(w.density_kg_m3, 950.0, 1100.0, "water.density_kg_m3", "kg/m^3");
}

// BG is what turns a steady roll into CG y: a wrong one is a wrong CG y.
std::optional<double> checkedBg(const std::optional<double>& bg_mm) {
  if (bg_mm && !(std::isfinite(*bg_mm) && *bg_mm > 0.0 && *bg_mm < 500.0))
    throw InputError("BG (CG below CB)", "value " + std::to_string(*bg_mm) + " mm is outside 0..500 mm",
                     "enter the BG of an inclining or roll test in mm, or leave it empty when not measured");
  return bg_mm;
}

// The level check narrows the analysis's prior on the pitch sensor's bias:
// a wrong one is a confident wrong net buoyancy.
std::optional<double> checkedLevelCheck(const std::optional<double>& deg) {
  if (deg && !(std::isfinite(*deg) && *deg > 0.0 && *deg <= 5.0))
    throw InputError("pitch sensor level check", "value " + std::to_string(*deg) + " deg is outside 0..5 deg",
                     "enter how closely the pitch sensor was checked level on the dock, e.g. 0.1, or leave it empty "
                     "when not checked");
  return deg;
}

void validate(const InstalledState& s) {
  for (const InstalledPoint& p : s.points) {
    const std::string field = "installed." + (p.name.empty() ? std::string("?") : p.name);
    if (p.name.empty())
      throw InputError(field, "adjustment point without a name", "name every point");
    requireRange(p.mass_kg, 0.0, 1e4, field + ".mass_kg", "kg");
    if (p.pieces_kg.empty()) continue;
    double sum = 0.0;
    for (double piece : p.pieces_kg) {
      requireRange(piece, 0.0, 1e3, field + ".pieces_kg", "kg");
      sum += piece;
    }
    if (std::abs(sum - p.mass_kg) > 1e-3)
      throw InputError(field, "pieces add up to " + std::to_string(sum) + " kg, not " +
                                  std::to_string(p.mass_kg) + " kg",
                       "list exactly the pieces installed at this point");
  }
  requireRange(s.total_mass_kg, 0.0, 1e5, "installed.total_mass_kg", "kg");
}

bool isLowerHex64(const std::string& s) {
  if (s.size() != 64) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}
}  // namespace

RecordId HistoryStore::ensureVehicle(const std::string& key, const std::string& name) {
  if (key.empty())
    throw InputError("vehicle", "empty vehicle key", "use the vehicle profile id, e.g. hugin1000");
  Transaction tx(*db_);
  auto ins = db_->prepare("INSERT INTO vehicles(key, name) VALUES (?1, ?2) ON CONFLICT(key) DO NOTHING");
  ins.bind(1, key).bind(2, name.empty() ? key : name).run();
  auto sel = db_->prepare("SELECT id FROM vehicles WHERE key = ?1");
  sel.bind(1, key);
  sel.step();
  const RecordId id = sel.integer(0);
  tx.commit();
  return id;
}

RecordId HistoryStore::addConfiguration(const Configuration& c) {
  requireValidConfigurationId(c.config_id);
  Transaction tx(*db_);
  if (configuration(c.config_id))
    throw InputError("configuration ID", "'" + c.config_id + "' already exists in '" + path() + "'",
                     "continue with the existing configuration or choose a new ID");
  const RecordId vehicle = ensureVehicle(c.vehicle_key, c.vehicle_name);
  const std::optional<double> bg = checkedBg(c.bg_mm);
  const std::optional<double> level = checkedLevelCheck(c.pitch_level_check_deg);
  auto st = db_->prepare("INSERT INTO configurations(config_id, vehicle_id, payload_note, area, water_type, created_at) "
                         "VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  st.bind(1, c.config_id).bind(2, vehicle).bind(3, c.payload_note).bind(4, c.area);
  st.bind(5, c.water_type).bind(6, toIsoUtc(c.created_at));
  st.run();
  const RecordId id = db_->lastInsertId();
  // The columns later schemas added (an older program's file has neither).
  if (has_bg_column_) db_->prepare("UPDATE configurations SET bg_mm = ?1 WHERE id = ?2").bind(1, bg).bind(2, id).run();
  if (has_level_check_column_)
    db_->prepare("UPDATE configurations SET pitch_level_check_deg = ?1 WHERE id = ?2").bind(1, level).bind(2, id).run();
  tx.commit();
  return id;
}

void HistoryStore::setConfigurationBg(const std::string& config_id, std::optional<double> bg_mm) {
  Transaction tx(*db_);
  auto st = db_->prepare("UPDATE configurations SET bg_mm = ?1 WHERE id = ?2");
  st.bind(1, checkedBg(bg_mm)).bind(2, configRow(config_id)).run();
  tx.commit();
}

void HistoryStore::setConfigurationPitchLevelCheck(const std::string& config_id, std::optional<double> deg) {
  Transaction tx(*db_);
  auto st = db_->prepare("UPDATE configurations SET pitch_level_check_deg = ?1 WHERE id = ?2");
  st.bind(1, checkedLevelCheck(deg)).bind(2, configRow(config_id)).run();
  tx.commit();
}

RecordId HistoryStore::addWeighing(const std::string& config_id, const Weighing& w) {
  Transaction tx(*db_);
  auto st = db_->prepare(
      "INSERT INTO weighings(configuration_id, at, method, inputs_json, results_json) "
      "VALUES (?1, ?2, ?3, ?4, ?5)");
  st.bind(1, configRow(config_id)).bind(2, toIsoUtc(w.at)).bind(3, toString(w.method));
  st.bind(4, w.inputs.dump()).bind(5, w.results.dump()).run();
  const RecordId id = db_->lastInsertId();
  tx.commit();
  return id;
}

RecordId HistoryStore::addWaterCondition(const std::string& config_id, const WaterCondition& w) {
  validate(w);
  Transaction tx(*db_);
  auto st = db_->prepare(
      "INSERT INTO water_conditions(configuration_id, measured_at, temperature_degc, "
      "salinity_psu, depth_m, density_kg_m3, source) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  st.bind(1, configRow(config_id)).bind(2, toIsoUtc(w.measured_at)).bind(3, w.temperature_degC);
  st.bind(4, w.salinity_psu).bind(5, w.depth_m).bind(6, w.density_kg_m3).bind(7, w.source).run();
  const RecordId id = db_->lastInsertId();
  tx.commit();
  return id;
}

RecordId HistoryStore::addMission(const std::string& config_id, const Mission& m) {
  if (!isLowerHex64(m.sha256))
    throw InputError("mission.sha256", "'" + m.sha256 + "' is not a SHA-256 hex digest",
                     "use sha256OfFile() on the mission file");
  Transaction tx(*db_);
  if (auto old = missionBySha256(config_id, m.sha256))
    throw InputError("mission file",
                     "'" + m.file_path + "' has the same content as mission #" +
                         std::to_string(old->id) + " ('" + old->file_path + "', imported " +
                         toIsoUtc(old->imported_at) + ") of " + config_id,
                     "nothing to do: this log is already in the history");
  auto st = db_->prepare(
      "INSERT INTO missions(configuration_id, imported_at, file_path, sha256, summary_json) "
      "VALUES (?1, ?2, ?3, ?4, ?5)");
  st.bind(1, configRow(config_id)).bind(2, toIsoUtc(m.imported_at)).bind(3, m.file_path);
  st.bind(4, m.sha256).bind(5, m.summary.dump()).run();
  const RecordId id = db_->lastInsertId();
  tx.commit();
  return id;
}

RecordId HistoryStore::importMissionFile(const std::string& config_id, const std::string& file,
                                         const nlohmann::json& summary, TimePoint imported_at) {
  Mission m;
  m.imported_at = imported_at;
  m.file_path = file;
  m.sha256 = sha256OfFile(file);
  m.summary = summary;
  return addMission(config_id, m);
}

RecordId HistoryStore::addAnalysisResult(const std::string& config_id, const AnalysisResult& a) {
  Transaction tx(*db_);
  auto st = db_->prepare(
      "INSERT INTO analysis_results(configuration_id, at, mission_id, result_json) "
      "VALUES (?1, ?2, ?3, ?4)");
  st.bind(1, configRow(config_id)).bind(2, toIsoUtc(a.at)).bind(3, a.mission_id);
  st.bind(4, a.result.dump()).run();
  const RecordId id = db_->lastInsertId();
  tx.commit();
  return id;
}

RecordId HistoryStore::addModelTerms(const std::string& config_id, const ModelTerms& m) {
  if (!m.model.is_object() || !m.model.contains("profile") || !m.model["profile"].is_object())
    throw InputError("model_terms.model.profile", "missing", "store the vehicle profile with the accepted terms written in");
  Transaction tx(*db_);
  auto st = db_->prepare("INSERT INTO model_terms(configuration_id, at, analysis_id, model_json) VALUES (?1, ?2, ?3, ?4)");
  st.bind(1, configRow(config_id)).bind(2, toIsoUtc(m.at)).bind(3, m.analysis_id).bind(4, m.model.dump()).run();
  const RecordId id = db_->lastInsertId();
  tx.commit();
  return id;
}

RecordId HistoryStore::addRecommendation(const std::string& config_id, const Recommendation& r) {
  if (r.policy.empty())
    throw InputError("recommendation.policy", "empty policy", "name the policy, e.g. exact");
  Transaction tx(*db_);
  auto st = db_->prepare(
      "INSERT INTO recommendations(configuration_id, at, analysis_id, policy, "
      "recommendation_json, accepted) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  st.bind(1, configRow(config_id)).bind(2, toIsoUtc(r.at)).bind(3, r.analysis_id);
  st.bind(4, r.policy).bind(5, r.recommendation.dump()).bind(6, r.accepted ? 1 : 0).run();
  const RecordId id = db_->lastInsertId();
  tx.commit();
  return id;
}

void HistoryStore::setRecommendationAccepted(RecordId id, bool accepted) {
  Transaction tx(*db_);
  auto st = db_->prepare("UPDATE recommendations SET accepted = ?2 WHERE id = ?1");
  st.bind(1, id).bind(2, accepted ? 1 : 0).run();
  if (db_->queryInt("SELECT changes()") != 1)
    throw InputError("recommendation", "no recommendation #" + std::to_string(id) + " in '" +
                                           path() + "'",
                     "pick a recommendation from this history");
  tx.commit();
}

RecordId HistoryStore::addInstalledState(const std::string& config_id, const InstalledState& s) {
  validate(s);
  Transaction tx(*db_);
  auto st = db_->prepare(
      "INSERT INTO installed_states(configuration_id, installed_at, recommendation_id, "
      "pieces_json, total_mass_kg, note) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  st.bind(1, configRow(config_id)).bind(2, toIsoUtc(s.installed_at)).bind(3, s.recommendation_id);
  st.bind(4, pointsToJson(s.points).dump()).bind(5, s.total_mass_kg).bind(6, s.note).run();
  const RecordId id = db_->lastInsertId();
  tx.commit();
  return id;
}

HistoryStore::PostMissionIds HistoryStore::savePostMission(const std::string& config_id,
                                                           const Mission& m, AnalysisResult a,
                                                           const std::optional<WaterCondition>& w) {
  Transaction tx(*db_);
  PostMissionIds ids;
  ids.mission = addMission(config_id, m);
  a.mission_id = ids.mission;
  ids.analysis = addAnalysisResult(config_id, a);
  if (w) ids.water = addWaterCondition(config_id, *w);
  tx.commit();
  return ids;
}

}  // namespace auv
