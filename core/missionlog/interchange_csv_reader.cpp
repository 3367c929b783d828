// Reader of the interchange CSV. Two paths per data row: a tight fast path
// (std::from_chars straight on the read buffer, no allocation, no field
// pre-scan) that accepts only perfectly regular rows, and a careful slow path
// that re-reads any row the fast path did not like, decides what is wrong and
// reports it. Time order is repaired after the whole file is read, because
// only then can a single wild time stamp be told from a clock that really went
// backwards.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <unordered_set>

#include "common/input_error.h"
#include "missionlog/decimal_parse.h"
#include "missionlog/decimal_overflow.h"
#include "missionlog/interchange_csv.h"
#include "missionlog/iso8601.h"
#include "missionlog/unit_conversion.h"

namespace auv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kMaxColumns = 100000;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

// A cell for a message: control and non-ASCII bytes escaped, length capped.
std::string printable(std::string_view s, std::size_t max = 24) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < max; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (s.size() > max) out += "...";
  return out;
}

std::string numberText(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

struct Cell {
  std::string_view text;
  std::size_t offset = 0;  // 0-based byte offset in the line
};

// Splits on commas; a comma inside double quotes does not split.
void splitCells(std::string_view line, std::vector<Cell>& out) {
  out.clear();
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) {
      out.push_back({line.substr(start, i - start), start});
      start = i + 1;
    }
  }
  out.push_back({line.substr(start), start});
}

// Strips surrounding quotes ("" inside stands for one quote).
std::string unquote(std::string_view s) {
  s = trim(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') {
    std::string out;
    for (std::size_t i = 1; i + 1 < s.size(); ++i) {
      out += s[i];
      if (s[i] == '"' && i + 2 < s.size() && s[i + 1] == '"') ++i;
    }
    return std::string(trim(out));
  }
  return std::string(s);
}

// One header cell, `name [unit]`; anything else is not well formed.
struct HeaderCell {
  std::string text;  // unquoted
  std::string name, unit;
  bool bracket = false;
  bool well_formed = true;
};

HeaderCell parseHeaderCell(std::string_view raw) {
  HeaderCell h;
  h.text = unquote(raw);
  const std::string_view t = h.text;
  const auto open = t.find('[');
  h.name = std::string(trim(t.substr(0, open)));
  if (open == std::string_view::npos) {
    h.well_formed = h.name.find(']') == std::string::npos;
    return h;
  }
  h.bracket = true;
  const auto close = t.find(']', open);
  if (close == std::string_view::npos) {
    h.unit = std::string(trim(t.substr(open + 1)));
    h.well_formed = false;
    return h;
  }
  h.unit = std::string(trim(t.substr(open + 1, close - open - 1)));
  h.well_formed = trim(t.substr(close + 1)).empty() && h.unit.find('[') == std::string::npos &&
                  h.name.find(']') == std::string::npos;
  return h;
}


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

class Parser {
 public:
  Parser(std::string file, const ReadOptions& o, ReadReport& r, std::uint64_t sizeHint)
      : file_(std::move(file)), opt_(o), rep_(r), size_hint_(sizeHint) {
    rep_.file = file_;
    rep_.format = "mission-log CSV v1";
  }

  // Complete lines: [b, e) with e[-1] == '\n'.
  void lines(const char* b, const char* e) {
    while (b < e && !in_data_) {
      const char* nl = static_cast<const char*>(std::memchr(b, '\n', static_cast<std::size_t>(e - b)));
      ++line_;
      preambleLine(std::string_view(b, static_cast<std::size_t>(nl - b)));
      b = nl + 1;
    }
    if (b < e) {
      if (!reserved_) reserveRows(b, e);
      dataLines(b, e);
    }
  }

  // The last line of the file when it has no line end.
  void finalLine(const char* b, const char* e) {
    ++line_;
    const std::string_view line(b, static_cast<std::size_t>(e - b));
    if (!in_data_) {
      preambleLine(line);
      return;
    }
    slowRow(line, true);
  }

  // A line longer than the read block, already skipped by the driver.
  void overlongLine() {
    ++line_;
    const std::string what = "line is longer than " + std::to_string(opt_.block_bytes) + " bytes";
    if (!in_data_)  // could have been the header: nothing after it can be trusted
      throw InputError("header", what + " before the header (binary data or no line ends?)",
                       "the file must be text with '\\n' or '\\r\\n' line ends and a "
                       "`name [unit]` header",
                       {file_, line_, 0});
    ++rep_.data_lines;
    ++rep_.rows_skipped;
    problem(ReadProblemKind::kOverlongLine, 0, "", what + " (binary data?); skipped",
            "remove the damaged part of the file");
  }

  MissionLog finish();

 private:
  struct Column {
    std::string name, unit, source_unit;
    UnitConversion conv;
    bool ignored = false;
  };

  void problem(ReadProblemKind kind, long column, std::string channel, std::string what,
               std::string fix) {
    ReadProblem p;
    p.kind = kind;
    p.where = {file_, line_, column};
    p.column = std::move(channel);
    p.problem = std::move(what);
    p.fix = std::move(fix);
    rep_.add(std::move(p), opt_.max_problems_per_kind);
  }

  void preambleLine(std::string_view line);
  void header(std::string_view line);
  void reserveRows(const char* b, const char* e);
  void dataLines(const char* p, const char* end);
  void slowRow(std::string_view line, bool finalNoNewline);
  void commitRow() {
    const std::size_t n = cols_.size();
    for (std::size_t c = 0; c < n; ++c) data_[c].push_back(row_[c]);
    row_line_.push_back(line_);
  }
  void repairTimeOrder();

  std::string file_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  std::uint64_t size_hint_;

  long long line_ = 0;
  bool in_data_ = false;
  bool reserved_ = false;
  bool iso_time_ = false;
  bool iso_no_zone_accepted_ = false;
  std::vector<MetadataEntry> meta_;
  std::vector<Column> cols_;
  std::size_t time_col_ = 0;
  std::vector<std::vector<double>> data_;
  std::vector<long long> row_line_;
  std::vector<double> row_;
  std::vector<Cell> cells_;
};

void Parser::preambleLine(std::string_view line) {
  if (line_ == 1) {
    if (line.size() >= 2 && ((line[0] == '\xFF' && line[1] == '\xFE') ||
                             (line[0] == '\xFE' && line[1] == '\xFF')))
      throw InputError("encoding", "the file is UTF-16 encoded", "save it as UTF-8",
                       {file_, 1, 1});
    if (line.size() >= 3 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
  }
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::string_view t = trim(line);
  if (t.empty()) return;
  if (t.front() == '#') {
    std::string_view body = trim(t.substr(1));
    const auto colon = body.find(':');
    if (colon == std::string_view::npos) {
      meta_.push_back({std::string(), std::string(body)});
    } else {
      meta_.push_back({std::string(trim(body.substr(0, colon))),
                       std::string(trim(body.substr(colon + 1)))});
    }
    return;
  }
  header(line);
}

void Parser::header(std::string_view line) {
  const InputLocation here{file_, line_, 1};
  if (line.find('\r') != std::string_view::npos)
    throw InputError("header", "lines end in a bare carriage return (classic Mac text)",
                     "convert the line ends to '\\n' or '\\r\\n'", here);
  splitCells(line, cells_);
  if (cells_.size() > kMaxColumns)
    throw InputError("header", "more than " + std::to_string(kMaxColumns) + " columns",
                     "this is not a mission log header", here);
  cols_.assign(cells_.size(), Column{});
  std::unordered_set<std::string> seen;
  bool haveTime = false;
  std::string timeLike;
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    Column& col = cols_[c];
    const long at = static_cast<long>(cells_[c].offset) + 1;
    const HeaderCell cell = parseHeaderCell(cells_[c].text);
    std::string name = cell.name;
    const std::string& unit = cell.unit;
    const bool unitWritten = cell.bracket;
    if (!cell.well_formed) {
      const bool delimiter = cell.text.find(';') != std::string::npos || cell.text.find('\t') != std::string::npos;
      const std::string what = "header cell '" + printable(cell.text, 60) + "' is not `name [unit]`" +
                               (delimiter ? " (this format is comma-separated; the file seems to use ';' or tabs)" : "");
      if (name == "time" || !canonicalUnitFor(name).empty())
        throw InputError(name, what, "write the column as `name [unit]`, columns separated by commas",
                         {file_, line_, at});
      col.ignored = true;
      problem(ReadProblemKind::kColumnIgnored, at, "", what + "; its values are ignored",
              "write the column as `name [unit]`");
      continue;
    }
    if (name.empty()) {
      col.ignored = true;
      problem(ReadProblemKind::kColumnIgnored, at, "",
              "header cell " + std::to_string(c + 1) + " has no name; its values are ignored",
              "name the column or remove it (a trailing comma makes an empty column)");
      continue;
    }
    if (seen.count(name)) {
      std::string renamed;
      for (int k = 2;; ++k) {
        renamed = name + "_" + std::to_string(k);
        if (!seen.count(renamed)) break;
      }
      problem(ReadProblemKind::kDuplicateColumn, at, name,
              "column name appears more than once; this one is renamed '" + renamed + "'",
              "give every column its own name");
      name = renamed;
    }
    seen.insert(name);
    col.name = name;
    col.source_unit = unit;
    col.unit = unit;

    if (name == "time" && !haveTime) {
      haveTime = true;
      time_col_ = c;
      if (iequals(unit, "iso8601") || iequals(unit, "iso")) {
        iso_time_ = true;
        col.unit = "s";
      } else if (unit.empty()) {
        col.unit = "s";
        problem(ReadProblemKind::kUnitAssumed, at, name,
                "no unit given; seconds assumed", "write `time [s]` or `time [iso8601]`");
      } else if (auto conv = unitConversion(unit, "s")) {
        col.conv = *conv;
        col.unit = "s";
      } else {
        throw InputError("time", "unit [" + unit + "] is not a time unit",
                         "write `time [s]` (seconds since `# start:`) or `time [iso8601]`",
                         {file_, line_, at});
      }
      continue;
    }
    if (timeLike.empty() && iequals(name.substr(0, 4), "time")) timeLike = cell.text;
    const std::string canonical(canonicalUnitFor(name));
    if (canonical.empty()) continue;  // extra channel: keeps its own unit
    if (!unitWritten || unit.empty()) {
      col.unit = canonical;
      problem(ReadProblemKind::kUnitAssumed, at, name,
              "no unit given; [" + canonical + "] (the format's unit for this column) assumed",
              "write `" + name + " [" + canonical + "]`");
      continue;
    }
    if (auto conv = unitConversion(unit, canonical)) {
      col.conv = *conv;
      col.unit = canonical;
      continue;
    }
    std::string accepted;
    for (const auto& u : unitsConvertibleTo(canonical)) accepted += (accepted.empty() ? "" : ", ") + u;
    throw InputError(name,
                     "unit [" + unit + "] cannot be converted to [" + canonical +
                         "], the unit the format defines for this column",
                     "write the column in one of: " + accepted, {file_, line_, at});
  }
  if (!haveTime) {
    std::string why;
    if (cells_.size() == 1 && (line.find(';') != std::string_view::npos ||
                               line.find('\t') != std::string_view::npos))
      why = "the header has a single cell: this format is comma-separated, the file seems to "
            "use ';' or tabs";
    else if (!timeLike.empty())
      why = "no column named exactly `time` (found '" + printable(timeLike, 40) + "')";
    else
      why = "no `time` column in the header line '" + printable(trim(line), 60) + "'";
    throw InputError("time", why,
                     "the first line after the `# key: value` metadata must be the header, "
                     "with a `time [s]` (seconds since `# start:`) or `time [iso8601]` column",
                     here);
  }
  data_.assign(cols_.size(), {});
  row_.assign(cols_.size(), kNaN);
  in_data_ = true;
}

void Parser::reserveRows(const char* b, const char* e) {
  reserved_ = true;
  // Average row length from the first rows, then room for the whole file.
  const std::size_t sample = std::min<std::size_t>(static_cast<std::size_t>(e - b), 1 << 16);
  const std::size_t rows = static_cast<std::size_t>(std::count(b, b + sample, '\n'));
  if (rows == 0) return;
  const double perRow = static_cast<double>(sample) / static_cast<double>(rows);
  double estimate = static_cast<double>(size_hint_) / perRow * 1.05 + 16.0;
  // A row has at least one byte per column (separators and the line end).
  estimate = std::min(estimate, static_cast<double>(size_hint_) / static_cast<double>(cols_.size()) + 16.0);
  const auto n = static_cast<std::size_t>(estimate);
  for (auto& d : data_) d.reserve(n);
  row_line_.reserve(n);
}

void Parser::dataLines(const char* p, const char* end) {
  const std::size_t n = cols_.size();
  double* row = row_.data();
  const double maxAbs = opt_.max_abs_value;
  const std::size_t timeCol = time_col_;
  const bool iso = iso_time_;
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

void Parser::slowRow(std::string_view line, bool finalNoNewline) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::string_view t = trim(line);
  if (t.empty()) return;
  if (t.front() == '#') {
    problem(ReadProblemKind::kCommentAfterHeader, 1, "", "comment line among the data rows; ignored",
            "put `# key: value` lines before the header");
    return;
  }
  ++rep_.data_lines;
  splitCells(line, cells_);
  const std::size_t n = cols_.size();
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
    if (iso_time_ && c == time_col_) {
      std::string_view s = trim(cell);
      if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = trim(s.substr(1, s.size() - 2));
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
        problem(ReadProblemKind::kNotANumber, at, cols_[c].name,
                "'" + printable(trim(cell)) + "' is not " +
                    (iso_time_ && c == time_col_ ? "an ISO 8601 time" : "a number") + "; row skipped",
                "correct the value, or leave the cell empty if nothing was sampled");
        return;
      case CellStatus::kTooLarge:
        if (c == time_col_) {
          ++rep_.rows_skipped;
          problem(ReadProblemKind::kValueOutOfRange, at, "time",
                  "time '" + printable(trim(cell)) + "' is infinite or beyond 1e30; row skipped",
                  "correct the time stamp");
          return;
        }
        row_[c] = kNaN;
        if (nBlanked < 8) blanked[nBlanked++] = c;
        else ++moreBlanked;
        break;
    }
  }
  if (std::isnan(row_[time_col_])) {
    ++rep_.rows_skipped;
    problem(ReadProblemKind::kMissingTime, static_cast<long>(cells_[time_col_].offset) + 1, "time",
            "time is empty or NaN; row skipped", "every row needs a time stamp");
    return;
  }
  for (std::size_t k = 0; k < nBlanked; ++k) {
    const std::size_t c = blanked[k];
    problem(ReadProblemKind::kValueOutOfRange, static_cast<long>(cells_[c].offset) + 1, cols_[c].name,
            "'" + printable(trim(cells_[c].text)) + "' is infinite or beyond +-" +
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

// Keeps the largest set of rows whose times do not decrease (longest
// non-decreasing subsequence), so one wild time stamp costs one row rather
// than every row after it; then merges rows that share a time stamp.
void Parser::repairTimeOrder() {
  std::vector<double>& t = data_[time_col_];
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
      ++rep_.rows_skipped;
      ReadProblem p;
      p.kind = ReadProblemKind::kTimeNotIncreasing;
      p.where = {file_, row_line_[i], 0};
      p.column = "time";
      p.problem = "time " + numberText(t[i]) + " s breaks the increasing order";
      if (lastKept >= 0)
        p.problem += " (previous kept row: line " + std::to_string(row_line_[static_cast<std::size_t>(lastKept)]) +
                     ", " + numberText(t[static_cast<std::size_t>(lastKept)]) + " s)";
      p.problem += "; row skipped";
      p.fix = "rows must be in time order; check the logger clock or sort the file";
      rep_.add(std::move(p), opt_.max_problems_per_kind);
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
    ++rep_.rows_merged;
    bool conflict = false;
    for (std::size_t c = 0; c < cols_.size(); ++c) {
      double& dst = data_[c][p];
      const double src = data_[c][i];
      if (std::isnan(dst)) {
        dst = src;
      } else if (!std::isnan(src) && src != dst && !conflict) {
        conflict = true;
        ReadProblem q;
        q.kind = ReadProblemKind::kConflictingDuplicate;
        q.where = {file_, row_line_[i], 0};
        q.column = cols_[c].name;
        q.problem = "value " + numberText(src) + " differs from " + numberText(dst) + " at line " +
                    std::to_string(row_line_[p]) + " with the same time; the first value is kept";
        q.fix = "remove the repeated row or correct its time";
        rep_.add(std::move(q), opt_.max_problems_per_kind);
      }
    }
    ReadProblem q;
    q.kind = ReadProblemKind::kDuplicateTime;
    q.where = {file_, row_line_[i], 0};
    q.column = "time";
    q.problem = "time " + numberText(t[i]) + " s repeats line " + std::to_string(row_line_[p]) +
                "; merged into that row (its empty cells filled from this one)";
    q.fix = "time must be strictly increasing; remove repeated rows";
    rep_.add(std::move(q), opt_.max_problems_per_kind);
  }
  std::size_t w = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!keep[i]) continue;
    if (w != i) {
      for (auto& col : data_) col[w] = col[i];
      row_line_[w] = row_line_[i];
    }
    ++w;
  }
  for (auto& col : data_) col.resize(w);
  row_line_.resize(w);
}

MissionLog Parser::finish() {
  if (!in_data_)
    throw InputError("header",
                     line_ == 0 ? "the file is empty" : "no header line (only metadata or blank lines)",
                     "after the `# key: value` lines the file needs a header such as "
                     "`time [s],depth [m]` and one row per sample",
                     {file_, line_, 0});
  if (row_line_.empty()) {
    std::string why = "no usable data rows";
    if (rep_.data_lines > 0)
      why += " (" + std::to_string(rep_.data_lines) + " data lines, all skipped; first: " +
             (rep_.problems.empty() ? std::string("?") : rep_.problems.front().text()) + ")";
    throw InputError("rows", why, "the file needs at least one row with a valid time",
                     {file_, line_, 0});
  }
  MissionLog log;
  log.metadata = std::move(meta_);
  // Conversions first, so that time order and duplicates are judged in seconds.
  for (std::size_t c = 0; c < cols_.size(); ++c)
    if (!cols_[c].conv.isIdentity() && !cols_[c].ignored)
      for (double& v : data_[c]) v = cols_[c].conv.apply(v);
  if (iso_time_) {
    std::vector<double>& t = data_[time_col_];
    std::optional<double> start = log.startEpochSeconds();
    if (!start) {
      start = *std::min_element(t.begin(), t.end());
      log.setMetadata("start", formatIso8601(*start, 3));
    }
    for (double& v : t) v -= *start;
  }
  repairTimeOrder();

  std::vector<double>& t = data_[time_col_];
  if (t.size() > 2) {
    std::vector<double> dt(t.size() - 1);
    for (std::size_t i = 1; i < t.size(); ++i) dt[i - 1] = t[i] - t[i - 1];
    auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
    std::nth_element(dt.begin(), mid, dt.end());
    const double limit = std::max(3600.0, 1000.0 * *mid);
    for (std::size_t i = 1; i < t.size(); ++i)
      if (t[i] - t[i - 1] > limit) {
        ReadProblem p;
        p.kind = ReadProblemKind::kTimeGap;
        p.where = {file_, row_line_[i], 0};
        p.column = "time";
        p.problem = numberText(t[i] - t[i - 1]) + " s without any row since line " +
                    std::to_string(row_line_[i - 1]) + " (typical step " + numberText(*mid) +
                    " s); nothing changed";
        p.fix = "check this time stamp if the logger did not really stop";
        rep_.add(std::move(p), opt_.max_problems_per_kind);
      }
  }

  log.time = std::move(data_[time_col_]);
  for (std::size_t c = 0; c < cols_.size(); ++c) {
    if (c == time_col_ || cols_[c].ignored) continue;
    LogChannel ch;
    ch.name = std::move(cols_[c].name);
    ch.unit = std::move(cols_[c].unit);
    ch.source_unit = std::move(cols_[c].source_unit);
    ch.values = std::move(data_[c]);
    if (ch.values.capacity() > ch.values.size() + ch.values.size() / 4) ch.values.shrink_to_fit();
    log.channels.push_back(std::move(ch));
  }
  if (log.time.capacity() > log.time.size() + log.time.size() / 4) log.time.shrink_to_fit();
  rep_.rows_kept = static_cast<long long>(log.time.size());
  rep_.lines = line_;
  return log;
}

// The block loop shared by files and memory: `pull` fills a buffer and
// returns the byte count (0 at the end).
template <class Pull>
MissionLog runParser(const std::string& name, std::uint64_t total, Pull pull,
                     const ReadOptions& options, ReadReport& report) {
  report = ReadReport{};
  const std::size_t cap = std::max<std::size_t>(options.block_bytes, 64);
  Parser parser(name, options, report, total);
  std::unique_ptr<char[]> buf(new char[cap]);
  std::size_t carry = 0;
  std::uint64_t consumed = 0;
  bool skipping = false;  // inside a line longer than the buffer
  if (options.progress && !options.progress(0.0)) throw ReadCancelled(name);
  for (;;) {
    const std::size_t got = pull(buf.get() + carry, cap - carry);
    if (got == 0) {
      if (skipping) parser.overlongLine();
      else if (carry > 0) parser.finalLine(buf.get(), buf.get() + carry);
      break;
    }
    consumed += got;
    const std::size_t avail = carry + got;
    char* b = buf.get();
    char* e = b + avail;
    const auto* lastNl = static_cast<const char*>(memrchr(b, '\n', avail));
    if (!lastNl) {
      if (avail == cap) {  // no line end in a full buffer: skip this line
        skipping = true;
        carry = 0;
      } else {
        carry = avail;
      }
    } else {
      const char* start = b;
      if (skipping) {
        const auto* firstNl = static_cast<const char*>(std::memchr(b, '\n', avail));
        parser.overlongLine();
        skipping = false;
        start = firstNl + 1;
      }
      parser.lines(start, lastNl + 1);
      carry = static_cast<std::size_t>(e - (lastNl + 1));
      std::memmove(b, lastNl + 1, carry);
    }
    if (options.progress && total > 0 &&
        !options.progress(std::min(1.0, static_cast<double>(consumed) / static_cast<double>(total))))
      throw ReadCancelled(name);
  }
  MissionLog log = parser.finish();
  if (options.progress && !options.progress(1.0)) throw ReadCancelled(name);
  return log;
}

template <class F>
MissionLog guardMemory(const std::string& name, F&& f) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw InputError("log", "not enough memory to hold this log", "split the file or use a larger machine",
                     {name, 0, 0});
  }
}

}  // namespace

bool InterchangeCsvReader::canRead(const std::filesystem::path&, std::string_view head) const {
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  while (!head.empty()) {
    const auto nl = head.find('\n');
    if (nl == std::string_view::npos) return false;  // header not within the sniffed bytes
    std::string_view line = head.substr(0, nl);
    head.remove_prefix(nl + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    std::vector<Cell> cells;
    splitCells(line, cells);
    for (const auto& c : cells) {
      const HeaderCell h = parseHeaderCell(c.text);
      if (h.name == "time" && h.well_formed) return true;
    }
    return false;
  }
  return false;
}

MissionLog InterchangeCsvReader::read(const std::filesystem::path& path, const ReadOptions& options,
                                      ReadReport& report) const {
  return readInterchangeCsv(path, options, report);
}

MissionLog readInterchangeCsv(const std::filesystem::path& path, const ReadOptions& options,
                              ReadReport& report) {
  const std::string name = path.string();
  const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw InputError("log", std::string("cannot open file: ") + std::strerror(errno),
                     "check the path and the file permissions", {name, 0, 0});
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || S_ISDIR(st.st_mode))
    throw InputError("log", "not a regular file", "give the path of a log file", {name, 0, 0});
  ::posix_fadvise(fd, 0, 0, POSIX_FADV_SEQUENTIAL);
  const auto total = static_cast<std::uint64_t>(st.st_size > 0 ? st.st_size : 0);
  auto pull = [&](char* dst, std::size_t n) -> std::size_t {
    for (;;) {
      const ssize_t r = ::read(fd, dst, n);
      if (r >= 0) return static_cast<std::size_t>(r);
      if (errno == EINTR) continue;
      throw InputError("log", std::string("read error: ") + std::strerror(errno),
                       "check the disk or copy the file again", {name, 0, 0});
    }
  };
  return guardMemory(name, [&] { return runParser(name, total, pull, options, report); });
}

MissionLog readInterchangeCsv(const std::filesystem::path& path) {
  ReadReport report;
  return readInterchangeCsv(path, ReadOptions{}, report);
}

MissionLog parseInterchangeCsv(std::string_view text, const std::string& sourceName,
                               const ReadOptions& options, ReadReport& report) {
  std::size_t pos = 0;
  auto pull = [&](char* dst, std::size_t n) -> std::size_t {
    const std::size_t k = std::min(n, text.size() - pos);
    if (k) std::memcpy(dst, text.data() + pos, k);
    pos += k;
    return k;
  };
  return guardMemory(sourceName, [&] { return runParser(sourceName, text.size(), pull, options, report); });
}

}  // namespace auv
