#include "missionlog/detail/interchange_rows.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "common/input_error.h"
#include "missionlog/decimal_overflow.h"
#include "missionlog/decimal_parse.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/iso8601.h"
#include "missionlog/log_table.h"

namespace auv::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum class CellStatus { kValue, kEmpty, kNotANumber, kTooLarge };

// The careful parse of one cell: blanks, quotes, NaN spellings, '+' signs.
CellStatus parseCellSlow(std::string_view cell, double& v) {
  cell = trim(cell);
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"')
    cell = trim(cell.substr(1, cell.size() - 2));
  if (cell.empty() || iequals(cell, "nan") || iequals(cell, "-nan") || iequals(cell, "+nan") ||
      iequals(cell, "na") || iequals(cell, "n/a") || iequals(cell, "null"))
    return CellStatus::kEmpty;
  std::string_view num = cell;
  if (num.front() == '+') {
    num.remove_prefix(1);
    if (num.empty() || num.front() == '-' || num.front() == '+') return CellStatus::kNotANumber;
  }
  const char* end = num.data() + num.size();
  const auto r = std::from_chars(num.data(), end, v);
  if (r.ptr != end || r.ec == std::errc::invalid_argument) return CellStatus::kNotANumber;
  if (r.ec == std::errc::result_out_of_range) {
    if (decimalOverflows(num)) return CellStatus::kTooLarge;
    v = num.front() == '-' ? -0.0 : 0.0;
    return CellStatus::kValue;
  }
  if (std::isnan(v)) return CellStatus::kEmpty;
  if (std::isinf(v)) return CellStatus::kTooLarge;
  return CellStatus::kValue;
}

}  // namespace

InterchangeRowReader::InterchangeRowReader(std::string file, InterchangeHeader header, long long line,
                                           std::uint64_t sizeHint, const ReadOptions& options, ReadReport& report)
    : file_(std::move(file)),
      header_(std::move(header)),
      opt_(options),
      rep_(report),
      size_hint_(sizeHint),
      line_(line) {
  data_.assign(header_.columns.size(), {});
  row_.assign(header_.columns.size(), kNaN);
}

void InterchangeRowReader::problem(ReadProblemKind kind, long column, std::string channel, std::string what,
                                   std::string fix) {
  reportProblem(rep_, opt_, kind, {file_, line_, column}, std::move(channel), std::move(what), std::move(fix));
}

void InterchangeRowReader::lines(const char* b, const char* e) {
  if (!reserved_) reserveRows(b, e);
  dataLines(b, e);
}

void InterchangeRowReader::finalLine(std::string_view line) {
  ++line_;
  slowRow(line, true);
}

void InterchangeRowReader::overlongLine() {
  ++line_;
  ++rep_.data_lines;
  ++rep_.rows_skipped;
  problem(ReadProblemKind::kOverlongLine, 0, "",
          "line is longer than " + std::to_string(opt_.block_bytes) + " bytes (binary data?); skipped",
          "remove the damaged part of the file");
}

void InterchangeRowReader::reserveRows(const char* b, const char* e) {
  reserved_ = true;
  // Average row length from the first rows, then room for the whole file.
  const std::size_t sample = std::min<std::size_t>(static_cast<std::size_t>(e - b), 1 << 16);
  const std::size_t rows = static_cast<std::size_t>(std::count(b, b + sample, '\n'));
  if (rows == 0) return;
  const double perRow = static_cast<double>(sample) / static_cast<double>(rows);
  double estimate = static_cast<double>(size_hint_) / perRow * 1.05 + 16.0;
  // A row has at least one byte per column (separators and the line end).
  estimate = std::min(estimate, static_cast<double>(size_hint_) / static_cast<double>(header_.columns.size()) + 16.0);
  const auto n = static_cast<std::size_t>(estimate);
  for (auto& d : data_) d.reserve(n);
  row_line_.reserve(n);
}

void InterchangeRowReader::dataLines(const char* p, const char* end) {
  const std::size_t n = header_.columns.size();
  double* row = row_.data();
  const double maxAbs = opt_.max_abs_value;
  const std::size_t timeCol = header_.time_column;
  const bool iso = header_.iso_time;
  while (p < end) {
    ++line_;
    const char* rowStart = p;
    bool ok = true;
    bool suspicious = false;
    for (std::size_t c = 0; c < n; ++c) {
      const char ch = *p;
      if (ch == ',' || ch == '\n' || ch == '\r') {
        row[c] = kNaN;
      } else if (iso && c == timeCol) {
        bool zone = false;
        const char* q = parseIso8601Prefix(p, end, row[c], zone);
        if (!q || (!zone && !iso_no_zone_accepted_)) {
          ok = false;
          break;
        }
        p = q;
      } else {
        const char* q = parseDecimal(p, end, row[c]);
        if (!q) {
          ok = false;
          break;
        }
        p = q;
        suspicious |= std::fabs(row[c]) > maxAbs;
      }
      if (c + 1 < n) {
        if (*p != ',') {
          ok = false;
          break;
        }
        ++p;
      }
    }
    if (ok) {
      if (*p == '\r') ++p;
      ok = *p == '\n';
    }
    if (ok && !suspicious && !std::isnan(row[timeCol])) {
      ++rep_.data_lines;
      commitRow();
      ++p;
    } else {
      const auto* nl = static_cast<const char*>(
          std::memchr(rowStart, '\n', static_cast<std::size_t>(end - rowStart)));
      slowRow(std::string_view(rowStart, static_cast<std::size_t>(nl - rowStart)), false);
      p = nl + 1;
    }
  }
}

void InterchangeRowReader::slowRow(std::string_view line, bool finalNoNewline) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::string_view t = trim(line);
  if (t.empty()) return;
  if (t.front() == '#') {
    problem(ReadProblemKind::kCommentAfterHeader, 1, "", "comment line among the data rows; ignored",
            "put `# key: value` lines before the header");
    return;
  }
  ++rep_.data_lines;
  splitAt(line, ',', cells_);
  const std::vector<InterchangeColumn>& cols = header_.columns;
  const std::size_t timeCol = header_.time_column;
  const bool iso = header_.iso_time;
  const std::size_t n = cols.size();
  const std::string counts = std::to_string(cells_.size()) + " cells, the header has " + std::to_string(n);
  if (cells_.size() < n) {
    ++rep_.rows_skipped;
    if (finalNoNewline)
      problem(ReadProblemKind::kTruncatedLine, static_cast<long>(line.size()) + 1, "",
              "the last line is cut short (" + counts + "); row skipped",
              "the file was probably copied while still being written; copy it again once the "
              "logger has closed it");
    else
      problem(ReadProblemKind::kWrongCellCount, 0, "", "row has " + counts + "; row skipped",
              "look for a missing or extra comma in this row");
    return;
  }
  for (std::size_t c = n; c < cells_.size(); ++c)
    if (!trim(cells_[c].text).empty()) {
      ++rep_.rows_skipped;
      problem(ReadProblemKind::kWrongCellCount, static_cast<long>(cells_[c].offset) + 1, "",
              "row has " + counts + "; row skipped", "look for a missing or extra comma in this row");
      return;
    }

  std::size_t blanked[8];
  std::size_t nBlanked = 0, moreBlanked = 0;
  for (std::size_t c = 0; c < n; ++c) {
    const std::string_view cell = cells_[c].text;
    const long at = static_cast<long>(cells_[c].offset) + 1;
    double v = kNaN;
    CellStatus st;
    if (iso && c == timeCol) {
      const std::string_view s = unquoted(cell);
      bool zone = false;
      const char* e = s.data() + s.size();
      const char* q = s.empty() ? nullptr : parseIso8601Prefix(s.data(), e, v, zone);
      if (q == e) {
        st = CellStatus::kValue;
        if (!zone && !iso_no_zone_accepted_) {
          iso_no_zone_accepted_ = true;
          problem(ReadProblemKind::kTimeZoneAssumed, at, "time",
                  "ISO 8601 time without a zone; read as UTC (noted once)",
                  "end the time stamps with 'Z' or an offset such as +02:00");
        }
      } else {
        st = parseCellSlow(cell, v) == CellStatus::kEmpty ? CellStatus::kEmpty : CellStatus::kNotANumber;
      }
    } else {
      st = parseCellSlow(cell, v);
    }
    if (st == CellStatus::kValue && std::fabs(v) > opt_.max_abs_value) st = CellStatus::kTooLarge;
    switch (st) {
      case CellStatus::kValue: row_[c] = v; break;
      case CellStatus::kEmpty: row_[c] = kNaN; break;
      case CellStatus::kNotANumber:
        ++rep_.rows_skipped;
        problem(ReadProblemKind::kNotANumber, at, cols[c].name,
                quotedCell(cell) + " is not " +
                    (iso && c == timeCol ? "an ISO 8601 time" : "a number") + "; row skipped",
                "correct the value, or leave the cell empty if nothing was sampled");
        return;
      case CellStatus::kTooLarge:
        if (c == timeCol) {
          ++rep_.rows_skipped;
          problem(ReadProblemKind::kValueOutOfRange, at, "time",
                  "time '" + printableText(trim(cell)) + "' is infinite or beyond 1e30; row skipped",
                  "correct the time stamp");
          return;
        }
        row_[c] = kNaN;
        if (nBlanked < 8) blanked[nBlanked++] = c;
        else ++moreBlanked;
        break;
    }
  }
  if (std::isnan(row_[timeCol])) {
    ++rep_.rows_skipped;
    problem(ReadProblemKind::kMissingTime, static_cast<long>(cells_[timeCol].offset) + 1, "time",
            "time is empty or NaN; row skipped", "every row needs a time stamp");
    return;
  }
  for (std::size_t k = 0; k < nBlanked; ++k) {
    const std::size_t c = blanked[k];
    problem(ReadProblemKind::kValueOutOfRange, static_cast<long>(cells_[c].offset) + 1, cols[c].name,
            quotedCell(cells_[c].text) + " is infinite or beyond +-" +
                numberText(opt_.max_abs_value) + " (a fill value or corruption); treated as not sampled",
            "leave cells empty where nothing was sampled");
  }
  rep_.cells_blanked += static_cast<long long>(nBlanked + moreBlanked);
  for (std::size_t k = 0; k < moreBlanked; ++k)
    rep_.counts[static_cast<std::size_t>(ReadProblemKind::kValueOutOfRange)]++;
  if (finalNoNewline)
    problem(ReadProblemKind::kNoFinalNewline, 0, "",
            "the last line has no line end; kept because it has all " + std::to_string(n) +
                " cells (its last value may still be cut short)",
            "end the file with a line break");
  commitRow();
}

}  // namespace auv::detail
