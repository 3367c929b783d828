#include "missionlog/detail/time_order.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "common/input_error.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/detail/table_rows.h"

namespace auv::detail {

void repairTimeOrder(LogTable& table, const ReadOptions& options, ReadReport& report) {
  std::vector<double>& t = table.time;
  const std::size_t n = t.size();
  bool ordered = true, strictly = true;
  for (std::size_t i = 1; i < n; ++i) {
    if (t[i] < t[i - 1]) ordered = false;
    if (!(t[i] > t[i - 1])) strictly = false;
  }
  if (strictly) return;
  std::vector<char> keep(n, 1);
  if (!ordered) {
    std::fill(keep.begin(), keep.end(), 0);
    std::vector<std::size_t> tails;
    std::vector<std::ptrdiff_t> parent(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
      auto it = std::upper_bound(tails.begin(), tails.end(), t[i],
                                 [&](double v, std::size_t idx) { return v < t[idx]; });
      const auto k = static_cast<std::size_t>(it - tails.begin());
      parent[i] = k ? static_cast<std::ptrdiff_t>(tails[k - 1]) : -1;
      if (it == tails.end()) tails.push_back(i);
      else *it = i;
    }
    for (auto i = static_cast<std::ptrdiff_t>(tails.back()); i >= 0; i = parent[static_cast<std::size_t>(i)])
      keep[static_cast<std::size_t>(i)] = 1;
    std::ptrdiff_t lastKept = -1;
    for (std::size_t i = 0; i < n; ++i) {
      if (keep[i]) {
        lastKept = static_cast<std::ptrdiff_t>(i);
        continue;
      }
      ++report.rows_skipped;
      std::string what = rowPrefix(table, i) + "time " + timeText(t[i], table.epoch) + " breaks the increasing order";
      if (lastKept >= 0) {
        const auto k = static_cast<std::size_t>(lastKept);
        what += " (previous kept row: " + rowName(table, k) + ", " + timeText(t[k], table.epoch) + ")";
      }
      reportProblem(report, options, ReadProblemKind::kTimeNotIncreasing, rowLocation(table, i), "time",
                    what + "; row skipped", "rows must be in time order; check the logger clock or sort the file");
    }
  }
  std::ptrdiff_t prev = -1;
  for (std::size_t i = 0; i < n; ++i) {
    if (!keep[i]) continue;
    if (prev < 0 || t[i] != t[static_cast<std::size_t>(prev)]) {
      prev = static_cast<std::ptrdiff_t>(i);
      continue;
    }
    const auto p = static_cast<std::size_t>(prev);
    keep[i] = 0;
    ++report.rows_merged;
    bool conflict = false;
    for (auto& c : table.columns) {
      if (c.values.empty()) continue;
      double& dst = c.values[p];
      const double src = c.values[i];
      if (std::isnan(dst)) {
        dst = src;
      } else if (!std::isnan(src) && src != dst && !conflict) {
        conflict = true;
        reportProblem(report, options, ReadProblemKind::kConflictingDuplicate, rowLocation(table, i), c.name,
                      rowPrefix(table, i) + "value " + numberText(src) + " differs from " + numberText(dst) + " at " +
                          rowName(table, p) + " with the same time; the first value is kept",
                      "remove the repeated row or correct its time");
      }
    }
    reportProblem(report, options, ReadProblemKind::kDuplicateTime, rowLocation(table, i), "time",
                  rowPrefix(table, i) + "time " + timeText(t[i], table.epoch) + " repeats " + rowName(table, p) +
                      "; merged into that row (its empty cells filled from this one)",
                  "time must be strictly increasing; remove repeated rows");
  }
  // Fewer than two rows left: say it is the time column, not "no depth".
  const auto kept = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1));
  if (kept < 2 && n >= 2) {
    throw InputError("time",
                     ordered ? "all " + std::to_string(n) + " rows have the same time " + timeText(t[0], table.epoch)
                             : "the times of the " + std::to_string(n) +
                                   " rows go backwards (no two rows in increasing order)",
                     "time must increase strictly from row to row (seconds since `# start:`, or a date and time); "
                     "check the time column and its format",
                     rowLocation(table, 1));
  }
  keepRows(table, keep);
}

void noteTimeGaps(const LogTable& table, const ReadOptions& options, ReadReport& report) {
  const std::vector<double>& t = table.time;
  if (t.size() <= 2) return;
  std::vector<double> dt(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) dt[i - 1] = t[i] - t[i - 1];
  auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
  std::nth_element(dt.begin(), mid, dt.end());
  const double limit = std::max(3600.0, 1000.0 * *mid);
  for (std::size_t i = 1; i < t.size(); ++i)
    if (t[i] - t[i - 1] > limit)
      reportProblem(report, options, ReadProblemKind::kTimeGap, rowLocation(table, i), "time",
                    rowPrefix(table, i) + numberText(t[i] - t[i - 1]) + " s without any row since " +
                        rowName(table, i - 1) + " (typical step " + numberText(*mid) + " s); nothing changed",
                    "check this time stamp if the logger did not really stop");
}

}  // namespace auv::detail
