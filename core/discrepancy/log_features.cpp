#include "discrepancy/log_features.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/series_tools.h"

namespace auv::discrepancy {

bool hasChannel(const MissionLog& log, const char* name, std::size_t min_samples) {
  const LogChannel* c = log.find(name);
  return c != nullptr && c->validCount() >= min_samples;
}

std::vector<double> channelAt(const MissionLog& log, const char* name, std::span<const double> times, bool hold,
                              double max_gap_s) {
  if (!hasChannel(log, name, 1)) return {};
  const TimeSeries s = log.series(name);
  analysis::SeriesCursor cur(s, hold, max_gap_s);
  std::vector<double> out(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) out[i] = cur.at(times[i]);
  return out;
}

std::vector<double> sinceLastChange(const MissionLog& log,
                                    std::initializer_list<std::pair<const char*, double>> channels,
                                    std::span<const double> times) {
  // Change instants of every listed channel, merged.
  std::vector<double> changes;
  for (const auto& [name, threshold] : channels) {
    if (!hasChannel(log, name, 2)) continue;
    const TimeSeries s = log.series(name);
    double ref = s.v.front();
    for (std::size_t i = 1; i < s.size(); ++i) {
      if (std::abs(s.v[i] - ref) > threshold) {
        changes.push_back(s.t[i]);
        ref = s.v[i];
      }
    }
  }
  std::sort(changes.begin(), changes.end());
  std::vector<double> out(times.size(), std::numeric_limits<double>::quiet_NaN());
  std::size_t j = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    while (j < changes.size() && changes[j] <= times[i]) ++j;
    if (j > 0) out[i] = times[i] - changes[j - 1];
  }
  return out;
}

}  // namespace auv::discrepancy
