#pragma once
// Time-order repair, the one rule of every reader
// (docs/decisions/missionlog-damaged-rows.md): it runs after the whole file is
// read, because only then can a single wild time stamp be told from a clock
// that really went backwards.
#include "missionlog/log_table.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv::detail {

// Keeps the largest set of rows whose times do not decrease (longest
// non-decreasing subsequence), so one wild time stamp costs one row rather
// than every row after it; then merges rows that share a time stamp (empty
// cells filled from the later row, the first value kept on a conflict).
// Counts rows_skipped and rows_merged and notes every dropped row.
void repairTimeOrder(LogTable& table, const ReadOptions& options, ReadReport& report);

// Notes (changes nothing) steps longer than an hour and 1000 typical steps:
// usually a wrong time stamp rather than a logger that stopped.
void noteTimeGaps(const LogTable& table, const ReadOptions& options, ReadReport& report);

}  // namespace auv::detail
