#include "missionlog/detail/slocum_channels.h"

#include <cmath>
#include <limits>
#include <map>

#include "missionlog/channel_aliases.h"
#include "missionlog/unit_spelling.h"

namespace auv::detail {
namespace {

// "comet-2016-174-05-000" -> "comet"
std::string gliderFromFileName(const std::string& f) {
  std::size_t cut = f.size();
  for (std::size_t i = 0; i + 5 < f.size(); ++i)
    if (f[i] == '-' && std::isdigit(static_cast<unsigned char>(f[i + 1])) &&
        std::isdigit(static_cast<unsigned char>(f[i + 4])) && f[i + 5] == '-') {
      cut = i;
      break;
    }
  return f.substr(0, cut);
}

}  // namespace

double slocumNmeaToDegrees(double v) {
  if (std::fabs(v) == kSlocumNoFix) return std::numeric_limits<double>::quiet_NaN();
  const double a = std::fabs(v);
  const double deg = std::floor(a / 100.0);
  return std::copysign(deg + (a - 100.0 * deg) / 60.0, v);
}

TableColumn slocumColumn(const std::string& sensor, const std::string& sensorUnit, const InputLocation& where,
                         bool& nmea) {
  TableColumn c;
  c.source_name = sensor;
  c.where = where;
  c.source_unit = sensorUnit;
  std::string unit = sensorUnit;
  const auto alias = findChannelAlias(normaliseChannelKey(sensor));
  if (alias && alias->channel != "time" && alias->channel != "date") {
    c.name = alias->channel;
    if (unit.empty()) unit = std::string(alias->unit);
  } else {
    c.name = safeChannelName(sensor);
  }
  nmea = unit == "lat" || unit == "lon";
  if (nmea) unit = "deg";
  c.unit = normaliseUnitSpelling(unit);
  return c;
}

MissionLog finishSlocumLog(std::vector<LogTable> streams, std::vector<MetadataEntry> tags, const ReadOptions& opt,
                           ReadReport& rep) {
  // Two sensors for one channel (m_de_oil_vol and m_ballast_pumped on a
  // glider that has only one engine): the one with more samples wins, the
  // other keeps its own name.
  const std::vector<TableColumn> layout = streams.empty() ? std::vector<TableColumn>{} : streams.front().columns;
  std::map<std::string, std::vector<std::size_t>> byName;
  for (std::size_t c = 0; c < layout.size(); ++c) byName[layout[c].name].push_back(c);
  for (auto& [name, idx] : byName) {
    if (idx.size() < 2) continue;
    auto samples = [&](std::size_t c) {
      std::size_t n = 0;
      for (const LogTable& t : streams)
        for (double v : t.columns[c].values) n += !std::isnan(v);
      return n;
    };
    std::size_t best = idx[0];
    for (std::size_t c : idx)
      if (samples(c) > samples(best)) best = c;
    for (std::size_t c : idx)
      if (c != best)
        for (LogTable& t : streams) {
          t.columns[c].name = safeChannelName(layout[c].source_name);
          t.columns[c].unit = normaliseUnitSpelling(layout[c].source_unit);
        }
  }
  std::vector<LogTable> tables;
  for (LogTable& t : streams)
    if (!t.time.empty()) {
      tidyTable(t, opt, rep);
      tables.push_back(std::move(t));
    }
  LogTable merged = mergeTables(std::move(tables), MergeNames::kCombine, opt, rep);
  merged.metadata = tags;
  for (const auto& t : tags)
    if (t.key == "filename" || t.key == "full_filename") {
      merged.metadata.push_back({"glider", gliderFromFileName(t.value)});
      break;
    }
  std::size_t empty = 0;
  for (const auto& c : merged.columns) {
    std::size_t valid = 0;
    for (double v : c.values) valid += !std::isnan(v);
    empty += valid == 0;
  }
  if (empty) merged.metadata.push_back({"sensors_never_sampled", std::to_string(empty) + " (not imported)"});
  return finishTable(std::move(merged), rep, true);
}

}  // namespace auv::detail
