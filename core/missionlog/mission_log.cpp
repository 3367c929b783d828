#include "missionlog/mission_log.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "common/input_error.h"
#include "missionlog/iso8601.h"

namespace auv {

std::size_t LogChannel::validCount() const {
  std::size_t n = 0;
  for (double v : values) n += !std::isnan(v);
  return n;
}

const std::string* MissionLog::metadataValue(std::string_view key) const {
  for (const auto& m : metadata)
    if (m.key == key) return &m.value;
  return nullptr;
}

void MissionLog::setMetadata(std::string key, std::string value) {
  for (auto& m : metadata)
    if (m.key == key) {
      m.value = std::move(value);
      return;
    }
  metadata.push_back({std::move(key), std::move(value)});
}

std::map<std::string, double> MissionLog::numericMetadata(std::string_view prefix) const {
  std::map<std::string, double> out;
  for (const auto& m : metadata) {
    if (m.key.compare(0, prefix.size(), prefix) != 0 || out.count(m.key)) continue;
    double v = 0;
    const char* end = m.value.data() + m.value.size();
    const auto r = std::from_chars(m.value.data(), end, v);
    if (r.ec == std::errc() && r.ptr == end && std::isfinite(v)) out.emplace(m.key, v);
  }
  return out;
}

std::map<std::string, double> MissionLog::seagliderConstants() const {
  std::map<std::string, double> out = numericMetadata("sg_cal_");
  out.merge(numericMetadata("log_"));
  return out;
}

std::optional<double> MissionLog::startEpochSeconds() const {
  const std::string* s = metadataValue("start");
  if (!s) return std::nullopt;
  return parseIso8601(*s);
}

const LogChannel* MissionLog::find(std::string_view name) const {
  for (const auto& c : channels)
    if (c.name == name) return &c;
  return nullptr;
}

LogChannel* MissionLog::find(std::string_view name) {
  for (auto& c : channels)
    if (c.name == name) return &c;
  return nullptr;
}

const LogChannel& MissionLog::channel(std::string_view name) const {
  if (const LogChannel* c = find(name)) return *c;
  std::string have;
  for (const auto& c : channels) have += (have.empty() ? "" : ", ") + c.name;
  throw InputError(std::string(name), "the log has no such channel (it has: " +
                                          (have.empty() ? std::string("none") : have) + ")",
                   "record or import a log that contains '" + std::string(name) + "'");
}

LogChannel& MissionLog::addChannel(std::string name, std::string unit) {
  if (name == "time" || find(name)) throw std::invalid_argument("channel '" + name + "' already exists");
  LogChannel c;
  c.name = std::move(name);
  c.source_unit = unit;
  c.unit = std::move(unit);
  c.values.assign(time.size(), std::nan(""));
  channels.push_back(std::move(c));
  return channels.back();
}

TimeSeries MissionLog::series(std::string_view name) const {
  const LogChannel& c = channel(name);
  TimeSeries s;
  const std::size_t n = std::min(c.values.size(), time.size());
  const std::size_t valid = c.validCount();
  s.t.reserve(valid);
  s.v.reserve(valid);
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isnan(c.values[i])) {
      s.t.push_back(time[i]);
      s.v.push_back(c.values[i]);
    }
  return s;
}

std::vector<double> MissionLog::validTimes(std::string_view name) const {
  return series(name).t;
}

}  // namespace auv
