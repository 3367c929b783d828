// Moving thesis ballasting files into and out of the history.
#include <algorithm>
#include <cctype>
#include <map>

#include "common/input_error.h"
#include "history/ballasting_file.h"
#include "history/store.h"
#include "history/transaction.h"

namespace auv {
namespace {

std::string vehicleKey(const std::string& type) {
  std::string key;
  for (char c : type)
    if (std::isalnum(static_cast<unsigned char>(c)))
      key += char(std::tolower(static_cast<unsigned char>(c)));
  return key;
}

struct Deviations {
  std::optional<double> depth_m, pitch_deg, roll_deg;
  bool any() const { return depth_m || pitch_deg || roll_deg; }
  bool operator==(const Deviations&) const = default;
};

std::optional<double> optNumber(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

Deviations deviationsOf(const nlohmann::json& result) {
  return {optNumber(result, kDepthDeviationKey), optNumber(result, kPitchDeviationKey),
          optNumber(result, kRollDeviationKey)};
}

nlohmann::json toJson(const Deviations& d, const std::string& source) {
  nlohmann::json j = {{"source", source}};
  if (d.depth_m) j[kDepthDeviationKey] = *d.depth_m;
  if (d.pitch_deg) j[kPitchDeviationKey] = *d.pitch_deg;
  if (d.roll_deg) j[kRollDeviationKey] = *d.roll_deg;
  return j;
}

void importRow(HistoryStore& store, const BallastingRow& row, const std::string& file,
               BallastingImport& result) {
  const std::string key = vehicleKey(row.vehicle_type);
  if (auto existing = store.configuration(row.config_id)) {
    if (existing->vehicle_key != key)
      throw InputError("Type",
                       "configuration " + row.config_id + " is a " + existing->vehicle_name +
                           " in the history, but this record says " + row.vehicle_type,
                       "a configuration ID names one vehicle; use another ID for this one",
                       {file, row.line, 0});
  } else {
    Configuration c;
    c.config_id = row.config_id;
    c.vehicle_key = key;
    c.vehicle_name = row.vehicle_type;
    c.area = row.area;
    c.payload_note = "imported from thesis ballasting file";
    c.created_at = row.at;
    store.addConfiguration(c);
  }
  if (auto last = store.latestInstalled(row.config_id, row.at); last && last->installed_at == row.at) {
    ++result.rows_already_present;
    return;
  }
  if (row.salinity_psu || row.temperature_degC) {
    const auto prev = store.latestWater(row.config_id, row.at);
    if (!prev || prev->salinity_psu != row.salinity_psu ||
        prev->temperature_degC != row.temperature_degC) {
      WaterCondition w;
      w.measured_at = row.at;
      w.salinity_psu = row.salinity_psu;
      w.temperature_degC = row.temperature_degC;
      w.source = "ballasting-file";
      store.addWaterCondition(row.config_id, w);
    }
  }
  const Deviations dev{row.depth_deviation_m, row.pitch_deviation_deg, row.roll_deviation_deg};
  if (dev.any()) {
    const auto prev = store.latestAnalysis(row.config_id, row.at);
    if (!prev || deviationsOf(prev->result) != dev) {
      AnalysisResult a;
      a.at = row.at;
      a.result = toJson(dev, "ballasting-file");
      store.addAnalysisResult(row.config_id, a);
    }
  }
  InstalledState s;
  s.installed_at = row.at;
  const auto names = ballastingPointNames(row.added_kg.size());
  for (std::size_t i = 0; i < row.added_kg.size(); ++i)
    s.points.push_back({names[i], row.added_kg[i], {}});
  s.total_mass_kg = row.total_weight_kg;
  s.note = "ballasting file line " + std::to_string(row.line);
  store.addInstalledState(row.config_id, s);
  ++result.rows_imported;
}
}  // namespace

BallastingImport importBallastingFile(HistoryStore& store, const BallastingFile& file,
                                      const std::string& file_name) {
  BallastingImport result;
  result.warnings = file.warnings;
  std::vector<BallastingRow> rows = file.rows;
  // Time order, so "what the history held before this row" is well defined.
  std::stable_sort(rows.begin(), rows.end(), [](const BallastingRow& a, const BallastingRow& b) {
    return a.config_id != b.config_id ? a.config_id < b.config_id : a.at < b.at;
  });
  Transaction tx(store.database());
  for (const BallastingRow& row : rows) importRow(store, row, file_name, result);
  tx.commit();
  return result;
}

std::vector<BallastingRow> ballastingRowsFromHistory(HistoryStore& store,
                                                     const std::string& config_id) {
  const auto config = store.configuration(config_id);
  if (!config)
    throw InputError("configuration ID", "'" + config_id + "' is not in the history '" +
                                             store.path() + "'",
                     "check the ID");
  std::vector<BallastingRow> rows;
  BallastingRow carried;
  carried.config_id = config->config_id;
  carried.vehicle_type = config->vehicle_name;
  carried.area = config->area;
  bool installed_seen = false;
  std::optional<TimePoint> group;  // minute of the events not yet written
  auto emit = [&] {
    if (group && installed_seen) {
      carried.at = *group;
      rows.push_back(carried);
    }
    group.reset();
  };
  for (const HistoryEvent& e : store.history(config_id)) {
    const auto* w = std::get_if<WaterCondition>(&e.record);
    const auto* a = std::get_if<AnalysisResult>(&e.record);
    const auto* s = std::get_if<InstalledState>(&e.record);
    const bool relevant = w || s || (a && deviationsOf(a->result).any());
    if (!relevant) continue;
    const TimePoint minute = std::chrono::floor<std::chrono::minutes>(e.at);
    if (group && *group != minute) emit();  // before this event changes the carried state
    group = minute;
    if (w) {
      if (w->salinity_psu) carried.salinity_psu = w->salinity_psu;
      if (w->temperature_degC) carried.temperature_degC = w->temperature_degC;
    } else if (a) {
      const Deviations d = deviationsOf(a->result);
      carried.depth_deviation_m = d.depth_m;
      carried.pitch_deviation_deg = d.pitch_deg;
      carried.roll_deviation_deg = d.roll_deg;
    } else {
      carried.added_kg.clear();
      for (const InstalledPoint& p : s->points) carried.added_kg.push_back(p.mass_kg);
      carried.total_weight_kg = s->total_mass_kg;
      installed_seen = !carried.added_kg.empty();
    }
  }
  emit();
  return rows;
}

std::string exportBallastingFile(HistoryStore& store, const std::string& config_id) {
  return formatBallastingFile(ballastingRowsFromHistory(store, config_id));
}

}  // namespace auv
