#include "history/export.h"

#include "common/input_error.h"
#include "history/number_text.h"
#include "history/store.h"

namespace auv {
namespace {

const char* kHistoryCsvColumns[] = {
    "timestamp",   "config_id", "kind",          "id",          "temperature_degC",
    "salinity_psu", "depth_m",  "density_kg_m3", "installed_kg", "total_mass_kg",
    "method",      "policy",    "accepted",      "file",        "sha256",
    "record_json"};

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

std::string num(const std::optional<double>& v) { return v ? formatShortest(*v) : ""; }

Configuration requireConfig(HistoryStore& store, const std::string& config_id) {
  auto c = store.configuration(config_id);
  if (!c)
    throw InputError("configuration ID",
                     "'" + config_id + "' is not in the history '" + store.path() + "'",
                     "check the ID");
  return *c;
}
}  // namespace

nlohmann::json exportHistoryJson(HistoryStore& store, const std::string& config_id) {
  const Configuration c = requireConfig(store, config_id);
  nlohmann::json events = nlohmann::json::array();
  for (const HistoryEvent& e : store.history(config_id)) events.push_back(toJson(e));
  return {{"format", "auvballast-history"},
          {"format_version", 1},
          {"schema_version", store.schemaVersion()},
          {"configuration", toJson(c)},
          {"events", std::move(events)}};
}

std::string exportHistoryCsv(HistoryStore& store, const std::string& config_id) {
  const Configuration c = requireConfig(store, config_id);
  std::string out;
  for (const char* col : kHistoryCsvColumns) {
    if (!out.empty()) out += ',';
    out += col;
  }
  out += "\r\n";
  for (const HistoryEvent& e : store.history(config_id)) {
    std::string cols[std::size(kHistoryCsvColumns)];
    cols[0] = toIsoUtc(e.at);
    cols[1] = c.config_id;
    cols[2] = toString(e.kind);
    cols[3] = std::to_string(e.id());
    if (const auto* w = std::get_if<WaterCondition>(&e.record)) {
      cols[4] = num(w->temperature_degC);
      cols[5] = num(w->salinity_psu);
      cols[6] = num(w->depth_m);
      cols[7] = num(w->density_kg_m3);
    } else if (const auto* s = std::get_if<InstalledState>(&e.record)) {
      for (const InstalledPoint& p : s->points) {
        if (!cols[8].empty()) cols[8] += ';';
        cols[8] += p.name + "=" + formatShortest(p.mass_kg);
      }
      cols[9] = num(s->total_mass_kg);
    } else if (const auto* wg = std::get_if<Weighing>(&e.record)) {
      cols[10] = toString(wg->method);
    } else if (const auto* r = std::get_if<Recommendation>(&e.record)) {
      cols[11] = r->policy;
      cols[12] = r->accepted ? "1" : "0";
    } else if (const auto* m = std::get_if<Mission>(&e.record)) {
      cols[13] = m->file_path;
      cols[14] = m->sha256;
    }
    cols[15] = toJson(e)["record"].dump();
    std::string line;
    for (std::size_t i = 0; i < std::size(cols); ++i) {
      if (i) line += ',';
      line += csvField(cols[i]);
    }
    out += line + "\r\n";
  }
  return out;
}

}  // namespace auv
