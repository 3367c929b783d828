#include "missionlog/detail/arrival_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "missionlog/detail/table_rows.h"

namespace auv::detail {

bool sortArrivalJitter(LogTable& t, double maxBackStep_s) {
  const std::size_t n = t.time.size();
  bool sorted = true;
  double runningMax = -INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(t.time[i])) return false;
    if (t.time[i] < runningMax) {
      sorted = false;
      if (runningMax - t.time[i] >= maxBackStep_s) return false;
    }
    runningMax = std::max(runningMax, t.time[i]);
  }
  if (sorted) return false;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.time[a] < t.time[b]; });
  auto permute = [&](auto& v) {
    if (v.size() != n) return;
    auto copy = v;
    for (std::size_t i = 0; i < n; ++i) v[i] = copy[order[i]];
  };
  permute(t.time);
  permute(t.row_where);
  for (auto& c : t.columns) permute(c.values);
  return true;
}

void mergeSameTimeRows(LogTable& t, SameTimeRows rule, ReadReport& report) {
  const std::size_t n = t.time.size();
  std::vector<char> keep(n, 1);
  bool any = false;
  for (std::size_t i = 1, prev = 0; i < n; ++i) {
    if (!(t.time[i] == t.time[prev])) {
      prev = i;
      continue;
    }
    if (rule == SameTimeRows::kMergeUnlessConflict) {
      bool conflict = false;
      for (const auto& c : t.columns)
        if (!c.values.empty() && !std::isnan(c.values[i]) && !std::isnan(c.values[prev]) &&
            c.values[i] != c.values[prev])
          conflict = true;
      if (conflict) {
        prev = i;
        continue;
      }
    }
    for (auto& c : t.columns) {
      if (c.values.empty() || std::isnan(c.values[i])) continue;
      if (rule == SameTimeRows::kLaterWins || std::isnan(c.values[prev])) c.values[prev] = c.values[i];
    }
    keep[i] = 0;
    any = true;
    ++report.rows_merged;
  }
  if (any) keepRows(t, keep);
}

}  // namespace auv::detail
