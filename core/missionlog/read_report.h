#pragma once
// What a reader did with a file that was usable but not perfect: every skipped
// row and blanked cell is counted, and the first few of each kind are kept
// with file, line, column, what was wrong and what to do. Readers throw
// InputError only when nothing sensible can be computed.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "common/input_error.h"

namespace auv {

enum class ReadProblemKind : int {
  kNotANumber,           // unparsable cell; row skipped
  kWrongCellCount,       // row skipped
  kMissingTime,          // empty/NaN time; row skipped
  kTimeNotIncreasing,    // row skipped to keep time strictly increasing
  kDuplicateTime,        // same time as the row before; merged into it
  kConflictingDuplicate, // ... and a cell disagreed; the first value was kept
  kValueOutOfRange,      // huge/inf/fill value; cell treated as not sampled
  kTruncatedLine,        // last line cut short; row skipped
  kOverlongLine,         // line longer than the read block; skipped
  kCommentAfterHeader,   // '#' line among the rows; ignored
  kUnitAssumed,          // table column without a unit; canonical unit assumed
  kColumnIgnored,        // header cell without a name; its values are ignored
  kDuplicateColumn,      // repeated column name; renamed
  kNoFinalNewline,       // last line has no line end but is complete; kept
  kTimeGap,              // unusually long gap between rows; nothing changed
  kTimeZoneAssumed,      // ISO time without zone read as UTC
  kCount
};

const char* toString(ReadProblemKind kind);

// True for kinds that removed a row from the result.
bool dropsRow(ReadProblemKind kind);

struct ReadProblem {
  ReadProblemKind kind = ReadProblemKind::kNotANumber;
  InputLocation where;  // file, 1-based line, 1-based character column (0 = whole line)
  std::string column;   // channel name, if one is concerned
  std::string problem;  // what was wrong and what the reader did
  std::string fix;      // what the user can do
  std::string text() const;  // "file:line:col: column: problem; fix"
};

struct ReadReport {
  std::string file;
  std::string format;
  long long lines = 0;          // physical lines seen
  long long data_lines = 0;     // lines after the header that were neither blank nor comments
  long long rows_kept = 0;      // rows in the result
  long long rows_skipped = 0;   // data lines dropped
  long long rows_merged = 0;    // duplicate-time rows merged into the previous row
  long long cells_blanked = 0;  // cells set to not-sampled (out of range)
  std::array<long long, static_cast<std::size_t>(ReadProblemKind::kCount)> counts{};
  std::vector<ReadProblem> problems;  // the first max_problems_per_kind of each kind

  long long count(ReadProblemKind kind) const { return counts[static_cast<std::size_t>(kind)]; }
  long long totalProblems() const;
  bool clean() const { return totalProblems() == 0; }
  // Counts the problem and keeps it if fewer than `keepPerKind` of its kind are kept.
  void add(ReadProblem p, std::size_t keepPerKind);
  // Short multi-line text for a CLI or a dialog: counts, then the kept problems.
  std::string summary() const;
};

}  // namespace auv
