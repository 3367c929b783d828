#include "wizard/history_save.h"

#include <cmath>

#include "analysis/analysis_report.h"
#include "common/input_error.h"
#include "firstmission/hugin_first_mission.h"
#include "history/first_mission_record.h"
#include "history/transaction.h"
#include "wizard/pre_mission_inputs.h"
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
    // A new roll test (or a corrected BG) and a new level check of the
    // pitch sensor belong to the configuration.
    const Configuration c = *store.configuration(s.configuration_id);
    if (c.bg_mm != s.bg_mm) store.setConfigurationBg(s.configuration_id, s.bg_mm);
    if (!s.isGlider() && c.pitch_level_check_deg != s.pitch_alignment_sigma_deg)
      store.setConfigurationPitchLevelCheck(s.configuration_id, s.pitch_alignment_sigma_deg);
    return;
  }
  Configuration c;
  c.config_id = s.configuration_id;
  c.vehicle_key = s.vehicle->id;
  c.vehicle_name = s.vehicle->name;
  c.payload_note = s.payload_note;
  c.area = s.area;
  c.water_type = s.water_type;
  c.bg_mm = s.bg_mm;
  if (!s.isGlider()) c.pitch_level_check_deg = s.pitch_alignment_sigma_deg;
  c.created_at = now;
  store.addConfiguration(c);
}

}  // namespace

void saveFirstMissionToHistory(HistoryStore& store, const WizardState& s, TimePoint now) {
  if (!s.report) throw InputError("result", "nothing computed yet", "go back and correct the highlighted field");
  const FirstMissionReport& r = *s.report;
  Transaction tx(store.database());
  ensureConfiguration(store, s, now);

  FirstMissionRecord record;
  record.tank = r.method == "tank";
  record.inputs = record.tank ? tankWeighingToJson(s.tank, s.tank_water_salt) : craneInputToJson(s.crane, s.vehicle->id);
  record.results = toJson(r);
  record.temperature_degC = r.temperature_degC;
  record.salinity_psu = r.salinity_psu;
  record.depth_m = r.depth_m;
  record.density_kg_m3 = r.density_kgm3;
  record.policy = record.tank ? "tank" : "exact";
  record.accepted = true;
  const RecordId rec_id = recordFirstMission(store, s.configuration_id, record, now);

  // What the technician says is installed now: the post-mission analysis
  // of the first mission starts from it.
  if (s.actually_installed_kg.size() == s.vehicle->points.size()) {
    InstalledState st;
    st.installed_at = now;
    st.recommendation_id = rec_id;
    for (std::size_t i = 0; i < s.vehicle->points.size(); ++i)
      st.points.push_back({s.vehicle->points[i].name, s.actually_installed_kg[i], {}});
    st.note = "first mission: installed after the weighing";
    store.addInstalledState(s.configuration_id, st);
  }
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

namespace {

// The mission, its analysis and accepted terms, for a configuration that is
// in the history (a new one was added by the caller in the same transaction).
RecordId saveMissionRecords(HistoryStore& store, const WizardState& s, TimePoint now) {
  if (!s.log) throw InputError("mission log", "no log imported", "import a log on the import page");
  const RecordId id = store.importMissionFile(s.configuration_id, s.log_file, missionSummaryJson(s), now);
  // The analysis with its mission: the next session plans from it (pre
  // mission), with the ballast state this session's plan used.
  if (const auto e = sessionEstimate(s)) {
    AnalysisResult a;
    a.at = now;
    a.mission_id = id;
    a.result = analysis::toJson(e->report);
    store.addAnalysisResult(s.configuration_id, a);
  }
  // Terms accepted in this session's model check become the configuration's model.
  if (s.model_profile.is_object() && s.model_profile != s.history_model) {
    ModelTerms m;
    m.at = now;
    nlohmann::json accepted = nlohmann::json::array();
    if (s.model_profile.contains("model_check") && s.model_profile["model_check"].contains("accepted"))
      accepted = s.model_profile["model_check"]["accepted"];
    m.model = {{"log", s.log_file}, {"accepted", accepted}, {"profile", s.model_profile}};
    store.addModelTerms(s.configuration_id, m);
  }
  return id;
}

}  // namespace

RecordId saveMissionToHistory(HistoryStore& store, const WizardState& s, TimePoint now) {
  if (!s.log) throw InputError("mission log", "no log imported", "import a log on the import page");
  Transaction tx(store.database());
  ensureConfiguration(store, s, now);
  const RecordId id = saveMissionRecords(store, s, now);
  tx.commit();
  return id;
}

PreMissionSaveIds savePreMissionToHistory(HistoryStore& store, const WizardState& s, const PlanBasis& basis,
                                          TimePoint now) {
  if (!s.plan || !s.vehicle) throw InputError("plan", "nothing planned yet", "go back to the pre-mission page");
  const VehicleProfile& v = *s.vehicle;
  const PreMissionPlan& plan = *s.plan;
  const std::vector<double> planned = installedAfterPlan(basis.installed_kg, plan);
  const std::vector<double>& actual = s.actually_installed_kg.size() == planned.size() ? s.actually_installed_kg : planned;
  PreMissionSaveIds ids;
  Transaction tx(store.database());
  ensureConfiguration(store, s, now);
  std::optional<RecordId> analysis_id = basis.analysis_id;
  if (s.mode == SessionMode::kPostMission && s.log) {
    ids.mission = saveMissionRecords(store, s, now);
    // The post-mission save may have stored this session's analysis with
    // the mission: the plan then links to that record.
    if (const auto a = store.latestAnalysis(s.configuration_id, now); a && a->mission_id == ids.mission) analysis_id = a->id;
  }

  // The next mission's water: entered now, or the last mission's CTD with
  // its own date, so that its age (thesis §5.5.3) stays true.
  const PlannedWater& w = plan.at_points.front().water;
  WaterCondition water;
  const bool operator_values = s.next_water_source == "operator";
  water.measured_at = operator_values ? now : basis.measured_at.value_or(now);
  water.temperature_degC = w.temperature_degC;
  water.salinity_psu = w.salinity_psu;
  water.depth_m = w.depth_m;
  water.density_kg_m3 = plan.at_points.front().state.density_kgm3;
  water.source = operator_values ? "operator" : "mission";
  ids.water = store.addWaterCondition(s.configuration_id, water);

  Recommendation rec;
  rec.at = now;
  rec.analysis_id = analysis_id;
  rec.policy = toString(plan.policy);
  rec.recommendation = preMissionReportJson(s, basis, toIsoUtc(now));
  rec.accepted = true;
  ids.recommendation = store.addRecommendation(s.configuration_id, rec);

  InstalledState st;
  st.installed_at = now;
  st.recommendation_id = ids.recommendation;
  bool differs = false;
  double change = 0.0;
  for (std::size_t i = 0; i < v.points.size(); ++i) {
    InstalledPoint p{v.points[i].name, actual[i], {}};
    const std::vector<int> counts = decomposeInstalled(actual[i], plan.piece_sizes_kg, v.points[i].name);
    for (std::size_t k = counts.size(); k-- > 0;)
      for (int n = 0; n < counts[k]; ++n) p.pieces_kg.push_back(plan.piece_sizes_kg[k]);
    st.points.push_back(p);
    differs = differs || std::abs(actual[i] - planned[i]) > 5e-5;
    change += actual[i] - (i < basis.installed_kg.size() ? basis.installed_kg[i] : 0.0);
  }
  if (basis.total_mass_kg) st.total_mass_kg = std::round((*basis.total_mass_kg + change) * 1e4) / 1e4;
  st.note = std::string("pre-mission plan (") + rec.policy + (differs ? "), installed differently" : "), installed as planned");
  ids.installed = store.addInstalledState(s.configuration_id, st);
  tx.commit();
  return ids;
}

}  // namespace auv::ui
