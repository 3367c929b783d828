#include "plot/plotted_window_csv.h"

#include <algorithm>
#include <cmath>

#include "missionlog/interchange_csv.h"

namespace auv::ui {

long writePlottedWindowCsv(const MissionLog& log, const std::vector<const LogChannel*>& channels, double x0_min,
                           double x1_min, const QString& log_name, const QString& path) {
  const double a = x0_min * 60.0, b = x1_min * 60.0;
  const auto lo = static_cast<std::size_t>(std::lower_bound(log.time.begin(), log.time.end(), a) - log.time.begin());
  const auto hi = static_cast<std::size_t>(std::upper_bound(log.time.begin(), log.time.end(), b) - log.time.begin());
  std::vector<std::size_t> rows;
  for (std::size_t i = lo; i < hi; ++i) {
    if (std::any_of(channels.begin(), channels.end(), [i](const LogChannel* c) { return !std::isnan(c->values[i]); }))
      rows.push_back(i);
  }
  MissionLog out;
  out.metadata = log.metadata;
  out.setMetadata("exported", QStringLiteral("plotted channels, %1-%2 min of %3")
                                  .arg(x0_min, 0, 'f', 3)
                                  .arg(x1_min, 0, 'f', 3)
                                  .arg(log_name)
                                  .toStdString());
  out.time.reserve(rows.size());
  for (std::size_t i : rows) out.time.push_back(log.time[i]);
  for (const LogChannel* c : channels) {
    LogChannel& o = out.addChannel(c->name, c->unit);
    for (std::size_t k = 0; k < rows.size(); ++k) o.values[k] = c->values[rows[k]];
  }
  writeInterchangeCsv(out, path.toStdString());
  return static_cast<long>(rows.size());
}

}  // namespace auv::ui
