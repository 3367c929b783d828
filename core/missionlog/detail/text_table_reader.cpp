#include "missionlog/detail/text_table_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/iso8601.h"
#include "missionlog/text_cells.h"
#include "missionlog/time_text.h"

namespace auv::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

void TextTableReader::prepare(std::string_view head, bool complete) {
  layout_ = sniffLayout(head, complete, map_, file_);
  plan_ = planColumns(layout_, map_, file_, opt_, rep_);
  nFields_ = layout_.fields.size();
  row_.assign(nFields_, kNaN);
  // Room for the whole file from the average length of the head's lines.
  const auto headLines = static_cast<double>(std::max<long long>(1, std::count(head.begin(), head.end(), '\n')));
  expectedRows_ = static_cast<std::size_t>(std::min(2e7, static_cast<double>(sizeHint_) / (static_cast<double>(head.size()) / headLines) * 1.05 + 16));
  plan_.table.time.reserve(expectedRows_);
  plan_.table.row_where.reserve(expectedRows_);
}

void TextTableReader::problem(ReadProblemKind kind, long column, std::string channel, std::string what,
                              std::string fix) {
  reportProblem(rep_, opt_, kind, {file_, line_, column}, std::move(channel), std::move(what), std::move(fix));
}

void TextTableReader::skip(ReadProblemKind kind, long column, std::string channel, std::string what,
                           std::string fix) {
  ++rep_.rows_skipped;
  problem(kind, column, std::move(channel), std::move(what), std::move(fix));
}

void TextTableReader::detectFormat(std::string_view c) {
  double e = 0, v = 0;
  bool zone = false;
  const char* end = c.data() + c.size();
  if (parseIso8601Prefix(c.data(), end, e, zone) == end) plan_.format = TimeFormat::kIso8601;
  else if (parseDayMonthYear(c)) plan_.format = TimeFormat::kDayMonthYear;
  else if (parseTimeOfDay(c)) plan_.format = TimeFormat::kTimeOfDay;
  else if (parseNumberCell(c, layout_.decimalComma, v) == CellValue::kNumber && std::isfinite(v))
    // Seconds beyond 1e8 (1973) are a clock, not a mission timer.
    plan_.format = (plan_.epochHint || std::fabs(v * plan_.timeScale) > 1e8) ? TimeFormat::kEpochSeconds
                                                                              : TimeFormat::kSeconds;
}

bool TextTableReader::parseTime(std::string_view cell, std::string_view dateCell, double& t) {
  const std::string_view c = unquoted(cell);
  if (isMissingSpelling(c)) {
    t = kNaN;
    return true;
  }
  if (plan_.format == TimeFormat::kAuto) {
    detectFormat(c);
    if (plan_.format == TimeFormat::kAuto) return false;
    plan_.table.epoch = plan_.format != TimeFormat::kSeconds &&
                        !(plan_.format == TimeFormat::kTimeOfDay && !plan_.dateField);
  }
  bool local = false;  // written without a zone
  switch (plan_.format) {
    case TimeFormat::kSeconds:
    case TimeFormat::kEpochSeconds: {
      double v = 0;
      if (parseNumberCell(c, layout_.decimalComma, v) != CellValue::kNumber) return false;
      t = v * plan_.timeScale;
      break;
    }
    case TimeFormat::kIso8601: {
      bool zone = false;
      const char* end = c.data() + c.size();
      if (c.empty() || parseIso8601Prefix(c.data(), end, t, zone) != end) return false;
      local = !zone;
      break;
    }
    case TimeFormat::kDayMonthYear: {
      const auto v = parseDayMonthYear(c);
      if (!v) return false;
      t = *v;
      local = true;
      break;
    }
    case TimeFormat::kTimeOfDay: {
      const auto v = parseTimeOfDay(c);
      if (!v) return false;
      if (plan_.dateField) {
        const auto d = parseDateOnly(unquoted(dateCell));
        if (!d) return false;
        t = *d + *v;
        local = true;
      } else {
        // Seconds since the first midnight; a jump back by more than 12 h is the next day.
        if (lastTod_ >= 0 && *v + todDay_ < lastTod_ - 43200.0) todDay_ += 86400.0;
        t = *v + todDay_;
        lastTod_ = t;
      }
      break;
    }
    case TimeFormat::kAuto: return false;
  }
  if (local) {
    if (map_.time.utc_offset_hours) {
      t -= *map_.time.utc_offset_hours * 3600.0;
    } else if (!zoneNoted_) {
      zoneNoted_ = true;
      problem(ReadProblemKind::kTimeZoneAssumed, 0, "time", "times are written without a zone; read as UTC (noted once)",
              "set \"utc_offset_hours\" in the column mapping if the logger ran on local time");
    }
  }
  plan_.table.epoch = plan_.format != TimeFormat::kSeconds && !(plan_.format == TimeFormat::kTimeOfDay && !plan_.dateField);
  return true;
}

bool TextTableReader::line(std::string_view text, LineFlag flag) {
  ++line_;
  if (line_ < layout_.dataFrom) return true;
  if (flag == LineFlag::kOverlong) {
    ++rep_.data_lines;
    skip(ReadProblemKind::kOverlongLine, 0, "",
         "line is longer than " + std::to_string(opt_.block_bytes) + " bytes (binary data?); skipped",
         "remove the damaged part of the file");
    return true;
  }
  const std::string_view trimmed = trim(text);
  if (trimmed.empty()) return true;
  if (isComment(trimmed)) {
    problem(ReadProblemKind::kCommentAfterHeader, 1, "", "comment line among the data rows; ignored",
            "put comments before the header");
    return true;
  }
  ++rep_.data_lines;
  splitLine(text, layout_.mode, false, cells_);
  const std::size_t n = nFields_;
  if (cells_.size() < n) {
    const std::string counts = std::to_string(cells_.size()) + " cells, the header has " + std::to_string(n);
    if (flag == LineFlag::kFinalNoNewline)
      skip(ReadProblemKind::kTruncatedLine, static_cast<long>(text.size()) + 1, "",
           "the last line is cut short (" + counts + "); row skipped",
           "the file was probably copied while still being written; copy it again once the logger has closed it");
    else
      skip(ReadProblemKind::kWrongCellCount, 0, "", "row has " + counts + "; row skipped",
           "look for a missing or extra delimiter in this row");
    return true;
  }
  for (std::size_t c = n; c < cells_.size(); ++c)
    if (!trim(cells_[c].text).empty()) {
      skip(ReadProblemKind::kWrongCellCount, static_cast<long>(cells_[c].offset) + 1, "",
           "row has " + std::to_string(cells_.size()) + " cells, the header has " + std::to_string(n) + "; row skipped",
           "look for a missing or extra delimiter in this row");
      return true;
    }
  double t = kNaN;
  const Cell& tc = cells_[plan_.timeField];
  const std::string_view dateCell = plan_.dateField ? cells_[*plan_.dateField].text : std::string_view();
  if (!parseTime(tc.text, dateCell, t)) {
    const bool dateBad = plan_.format == TimeFormat::kTimeOfDay && plan_.dateField && !parseDateOnly(unquoted(dateCell));
    const Cell& bad = dateBad ? cells_[*plan_.dateField] : tc;
    skip(ReadProblemKind::kNotANumber, static_cast<long>(bad.offset) + 1, "time",
         quotedCell(bad.text) + " is not " +
             (dateBad ? std::string("a date (dd.mm.yyyy or yyyy-mm-dd)")
                      : plan_.format == TimeFormat::kAuto ? std::string("a time")
                                                          : std::string("a time in the format ") + toString(plan_.format)) +
             "; row skipped",
         "correct the time stamp; every row needs one");
    return true;
  }
  for (std::size_t c = 0; c < n; ++c) {
    const int target = plan_.target[c];
    if (target < 0) continue;
    double v = kNaN;
    switch (parseNumberCell(cells_[c].text, layout_.decimalComma, v)) {
      case CellValue::kNumber: break;
      case CellValue::kEmpty: v = kNaN; break;
      case CellValue::kBad: {
        const auto& col = plan_.table.columns[static_cast<std::size_t>(target)];
        skip(ReadProblemKind::kNotANumber, static_cast<long>(cells_[c].offset) + 1, col.name,
             quotedCell(cells_[c].text) + " is not a number; row skipped",
             "correct the value, or leave the cell empty if nothing was sampled");
        return true;
      }
    }
    row_[c] = v;
  }
  if (flag == LineFlag::kFinalNoNewline)
    problem(ReadProblemKind::kNoFinalNewline, 0, "",
            "the last line has no line end; kept because it has all " + std::to_string(n) +
                " cells (its last value may still be cut short)",
            "end the file with a line break");
  // Commit; a column allocates only once it has a sample (wide logs are mostly empty).
  const std::size_t rowIndex = plan_.table.time.size();
  plan_.table.time.push_back(t);
  plan_.table.row_where.push_back(line_);
  for (std::size_t c = 0; c < n; ++c) {
    const int target = plan_.target[c];
    if (target < 0) continue;
    auto& vals = plan_.table.columns[static_cast<std::size_t>(target)].values;
    const double v = row_[c];
    if (vals.empty()) {
      if (std::isnan(v)) continue;
      vals.reserve(std::max(expectedRows_, rowIndex + 1));
      vals.assign(rowIndex, kNaN);
    }
    vals.push_back(v);
  }
  return true;
}

LogTable TextTableReader::finish() {
  rep_.lines += line_;
  LogTable table = std::move(plan_.table);
  if (table.time.empty()) {
    std::string why = "no usable data rows";
    if (rep_.data_lines > 0)
      why += " (" + std::to_string(rep_.data_lines) + " data lines, all skipped; first: " +
             (rep_.problems.empty() ? std::string("?") : rep_.problems.front().text()) + ")";
    throw InputError("rows", why, "the file needs at least one row with a valid time", {file_, line_, 0});
  }
  table.metadata = layout_.preamble;
  for (const auto& e : map_.metadata) table.metadata.push_back(e);
  return table;
}

}  // namespace auv::detail
