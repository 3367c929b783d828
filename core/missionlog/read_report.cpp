#include "missionlog/read_report.h"

namespace auv {

const char* toString(ReadProblemKind k) {
  switch (k) {
    case ReadProblemKind::kNotANumber: return "not a number";
    case ReadProblemKind::kWrongCellCount: return "wrong number of cells";
    case ReadProblemKind::kMissingTime: return "missing time";
    case ReadProblemKind::kTimeNotIncreasing: return "time not increasing";
    case ReadProblemKind::kDuplicateTime: return "duplicate time";
    case ReadProblemKind::kConflictingDuplicate: return "conflicting duplicate";
    case ReadProblemKind::kValueOutOfRange: return "value out of range";
    case ReadProblemKind::kTruncatedLine: return "truncated line";
    case ReadProblemKind::kOverlongLine: return "overlong line";
    case ReadProblemKind::kCommentAfterHeader: return "comment among rows";
    case ReadProblemKind::kUnitAssumed: return "unit assumed";
    case ReadProblemKind::kColumnIgnored: return "column ignored";
    case ReadProblemKind::kDuplicateColumn: return "duplicate column";
    case ReadProblemKind::kNoFinalNewline: return "no final line end";
    case ReadProblemKind::kTimeGap: return "time gap";
    case ReadProblemKind::kTimeZoneAssumed: return "time zone assumed";
    case ReadProblemKind::kCount: break;
  }
  return "?";
}

bool dropsRow(ReadProblemKind k) {
  switch (k) {
    case ReadProblemKind::kNotANumber:
    case ReadProblemKind::kWrongCellCount:
    case ReadProblemKind::kMissingTime:
    case ReadProblemKind::kTimeNotIncreasing:
    case ReadProblemKind::kTruncatedLine:
    case ReadProblemKind::kOverlongLine: return true;
    default: return false;
  }
}

std::string ReadProblem::text() const {
  std::string s = formatLocation(where);
  if (!column.empty()) s += column + ": ";
  s += problem;
  if (!fix.empty()) s += "; " + fix;
  return s;
}

long long ReadReport::totalProblems() const {
  long long n = 0;
  for (long long c : counts) n += c;
  return n;
}

void ReadReport::add(ReadProblem p, std::size_t keepPerKind) {
  const auto k = static_cast<std::size_t>(p.kind);
  if (static_cast<std::size_t>(counts[k]) < keepPerKind) problems.push_back(std::move(p));
  ++counts[k];
}

std::string ReadReport::summary() const {
  std::string s = file + ": " + std::to_string(rows_kept) + " rows read";
  if (rows_skipped) s += ", " + std::to_string(rows_skipped) + " skipped";
  if (rows_merged) s += ", " + std::to_string(rows_merged) + " merged (duplicate time)";
  if (cells_blanked) s += ", " + std::to_string(cells_blanked) + " cells blanked";
  s += "\n";
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (counts[k])
      s += "  " + std::to_string(counts[k]) + " x " + toString(static_cast<ReadProblemKind>(k)) + "\n";
  for (const auto& p : problems) s += "  " + p.text() + "\n";
  return s;
}

}  // namespace auv
