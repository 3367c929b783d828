#include "wizard/history_save.h"

#include "common/input_error.h"
#include "history/transaction.h"
#include "wizard/session_json.h"

namespace auv::ui {
namespace {

void ensureConfiguration(HistoryStore& store, const WizardState& s, TimePoint now) {
  if (!s.vehicle) throw InputError("vehicle", "no vehicle chosen", "go back to the vehicle page");
  if (store.configuration(s.configuration_id)) {
    if (!s.configuration_in_history) {
      throw InputError("configuration ID", "'" + s.configuration_id + "' already exists in the history",
                       "pick it on the start page or choose a new ID");
    }
    return;
  }
  Configuration c;
  c.config_id = s.configuration_id;
  c.vehicle_key = s.vehicle->id;
  c.vehicle_name = s.vehicle->name;
  c.payload_note = s.payload_note;
  c.area = s.area;
  c.water_type = s.water_type;
  c.created_at = now;
  store.addConfiguration(c);
}

}  // namespace

void saveFirstMissionToHistory(HistoryStore& store, const WizardState& s, TimePoint now) {
  if (!s.report) throw InputError("result", "nothing computed yet", "go back and correct the highlighted field");
  const FirstMissionReport& r = *s.report;
  Transaction tx(store.database());
  ensureConfiguration(store, s, now);

  Weighing w;
  w.at = now;
  const bool tank = r.method == "tank";
  w.method = tank ? WeighingMethod::kTank : WeighingMethod::kCrane;
  w.inputs = tank ? tankWeighingToJson(s.tank, s.tank_water_salt) : craneInputToJson(s.crane, s.vehicle->id);
  w.results = toJson(r);
  store.addWeighing(s.configuration_id, w);

  WaterCondition water;
  water.measured_at = now;
  water.temperature_degC = r.temperature_degC;
  water.salinity_psu = r.salinity_psu;
  water.depth_m = r.depth_m;
  water.density_kg_m3 = r.density_kgm3;
  water.source = "operator";
  store.addWaterCondition(s.configuration_id, water);

  Recommendation rec;
  rec.at = now;
  rec.policy = tank ? "tank" : "exact";
  rec.recommendation = toJson(r);
  rec.accepted = true;
  store.addRecommendation(s.configuration_id, rec);
  tx.commit();
}

nlohmann::json missionSummaryJson(const WizardState& s) {
  nlohmann::json j;
  j["format"] = s.log_format;
  if (s.log) {
    j["rows"] = s.log->rowCount();
    j["duration_s"] = s.log->duration();
    nlohmann::json ch = nlohmann::json::array();
    for (const auto& c : s.log->channels) ch.push_back(c.name + " [" + c.unit + "]");
    j["channels"] = ch;
  }
  if (s.log_report) {
    const ReadReport& r = *s.log_report;
    j["rows_kept"] = r.rows_kept;
    j["rows_skipped"] = r.rows_skipped;
    j["rows_merged"] = r.rows_merged;
    j["cells_blanked"] = r.cells_blanked;
    nlohmann::json problems = nlohmann::json::object();
    for (int k = 0; k < static_cast<int>(ReadProblemKind::kCount); ++k) {
      const auto kind = static_cast<ReadProblemKind>(k);
      if (r.count(kind) > 0) problems[toString(kind)] = r.count(kind);
    }
    j["problems"] = problems;
  }
  return j;
}

RecordId saveMissionToHistory(HistoryStore& store, const WizardState& s, TimePoint now) {
  if (!s.log) throw InputError("mission log", "no log imported", "import a log on the import page");
  Transaction tx(store.database());
  ensureConfiguration(store, s, now);
  const RecordId id = store.importMissionFile(s.configuration_id, s.log_file, missionSummaryJson(s), now);
  tx.commit();
  return id;
}

}  // namespace auv::ui
