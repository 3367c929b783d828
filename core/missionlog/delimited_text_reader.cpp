// The delimited-text reader works in two passes over the start of the file and
// one over all of it: the layout (delimiter, header line, units line, decimal
// mark) is decided on up to 500 lines from the head, the columns are planned
// from the header and the mapping, then every line is read in blocks.
#include "missionlog/delimited_text_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <unordered_set>

#include "common/input_error.h"
#include "missionlog/channel_aliases.h"
#include "missionlog/iso8601.h"
#include "missionlog/log_table.h"
#include "missionlog/text_cells.h"
#include "missionlog/text_lines.h"
#include "missionlog/time_text.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"

namespace auv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kHeadBytes = 256 * 1024;
constexpr std::size_t kHeadLines = 500;
constexpr std::size_t kMaxColumns = 10000;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string o(s);
  for (char& c : o)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return o;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool isComment(std::string_view t) {
  return !t.empty() && (t.front() == '#' || t.front() == '%' || t.substr(0, 2) == "//");
}

struct Cell {
  std::string_view text;
  std::size_t offset = 0;  // 0-based byte offset in the line
};

struct Mode {
  char delim = ',';  // 0 = runs of blanks
  bool joinDateTime = false;
};

std::string describe(Mode m) {
  switch (m.delim) {
    case ',': return "comma";
    case ';': return "semicolon";
    case '\t': return "tab";
    default: return m.joinDateTime ? "whitespace (date and time joined)" : "whitespace";
  }
}

// dd.mm.yyyy or yyyy-mm-dd
bool looksLikeDate(std::string_view t) {
  if (t.size() != 10) return false;
  const bool dmy = t[2] == '.' && t[5] == '.' && isDigit(t[0]) && isDigit(t[1]) && isDigit(t[3]) && isDigit(t[4]) &&
                   isDigit(t[6]) && isDigit(t[9]);
  const bool ymd = t[4] == '-' && t[7] == '-' && isDigit(t[0]) && isDigit(t[3]) && isDigit(t[5]) && isDigit(t[8]);
  return dmy || ymd;
}

bool looksLikeClock(std::string_view t) {
  return t.size() >= 4 && isDigit(t[0]) && (t[1] == ':' || (isDigit(t[1]) && t[2] == ':'));
}

void splitLine(std::string_view line, Mode mode, bool header, std::vector<Cell>& out) {
  out.clear();
  if (mode.delim) {
    const char d = mode.delim;
    if (line.find('"') == std::string_view::npos) {
      std::size_t start = 0;
      for (;;) {
        const auto p = line.find(d, start);
        if (p == std::string_view::npos) {
          out.push_back({line.substr(start), start});
          return;
        }
        out.push_back({line.substr(start, p - start), start});
        start = p + 1;
      }
    }
    std::size_t start = 0;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '"') quoted = !quoted;
      else if (line[i] == d && !quoted) {
        out.push_back({line.substr(start, i - start), start});
        start = i + 1;
      }
    }
    out.push_back({line.substr(start), start});
    return;
  }
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= n) break;
    const std::size_t s = i;
    while (i < n && line[i] != ' ' && line[i] != '\t') ++i;
    const std::string_view tok = line.substr(s, i - s);
    if (!out.empty()) {
      Cell& prev = out.back();
      const bool join = header ? (tok.front() == '(' || tok.front() == '[' || tok.front() == '{')
                               : (mode.joinDateTime && looksLikeDate(prev.text) && looksLikeClock(tok));
      if (join) {
        prev.text = line.substr(prev.offset, i - prev.offset);
        continue;
      }
    }
    out.push_back({tok, s});
  }
}

std::string_view unquoted(std::string_view c) {
  c = trim(c);
  if (c.size() >= 2 && c.front() == '"' && c.back() == '"') c = trim(c.substr(1, c.size() - 2));
  return c;
}

bool isAbsoluteTimeText(std::string_view c) {
  double e = 0;
  bool zone = false;
  const char* end = c.data() + c.size();
  return (!c.empty() && parseIso8601Prefix(c.data(), end, e, zone) == end) || parseDayMonthYear(c) ||
         parseTimeOfDay(c) || parseDateOnly(c);
}

bool valueLike(std::string_view cell, bool decimalComma) {
  const std::string_view c = unquoted(cell);
  double v = 0;
  return parseNumberCell(c, decimalComma, v) != CellValue::kBad || isAbsoluteTimeText(c);
}

bool unitLike(std::string_view cell) {
  const std::string_view c = unquoted(cell);
  if (c.empty() || c == "-") return true;
  if (c.size() >= 2 && ((c.front() == '[' && c.back() == ']') || (c.front() == '(' && c.back() == ')'))) return true;
  return isKnownUnit(normaliseUnitSpelling(c)) || lower(c) == "timestamp";
}

std::string stripBrackets(std::string_view c) {
  c = unquoted(c);
  if (c.size() >= 2 && ((c.front() == '[' && c.back() == ']') || (c.front() == '(' && c.back() == ')')))
    c = trim(c.substr(1, c.size() - 2));
  return c == "-" ? std::string() : std::string(c);
}

struct HeadLine {
  std::string_view text;
  long long line = 0;
};

struct Layout {
  Mode mode;
  bool decimalComma = false;
  long long headerLine = 0;
  long long dataFrom = 0;  // first line of the table body
  std::vector<HeaderField> fields;
  std::vector<long> fieldColumn;  // 1-based character column of each header cell
  std::vector<char> textColumn;   // holds only text in the sampled rows
  std::vector<MetadataEntry> preamble;
};

MetadataEntry preambleEntry(std::string_view t) {
  if (isComment(t)) t = trim(t.substr(t.front() == '/' ? 2 : 1));
  const auto colon = t.find(':');
  if (colon == std::string_view::npos || colon == 0 || colon > 40) return {std::string(), std::string(t)};
  return {std::string(trim(t.substr(0, colon))), std::string(trim(t.substr(colon + 1)))};
}

Layout sniffLayout(std::string_view head, bool complete, const ColumnMapping& mapping, const std::string& file) {
  if (head.size() >= 2 && ((head[0] == '\xFF' && head[1] == '\xFE') || (head[0] == '\xFE' && head[1] == '\xFF')))
    throw InputError("encoding", "the file is UTF-16 encoded", "save it as UTF-8", {file, 1, 1});
  if (const auto nul = head.find('\0'); nul != std::string_view::npos) {
    const long line = static_cast<long>(std::count(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(nul), '\n')) + 1;
    throw InputError("encoding", "the file contains NUL bytes: binary data (or UTF-16 text), not a text log",
                     "export the log as plain text, or use the reader for its binary format", {file, line, 0});
  }
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  std::vector<HeadLine> lines_;  // non-blank
  long long lineNo = 0;
  while (!head.empty() && lines_.size() < kHeadLines) {
    const auto nl = head.find('\n');
    if (nl == std::string_view::npos && !complete) break;
    std::string_view l = head.substr(0, nl);
    head.remove_prefix(nl == std::string_view::npos ? head.size() : nl + 1);
    ++lineNo;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    if (l.find('\r') != std::string_view::npos)
      throw InputError("line ends", "lines end in a bare carriage return (classic Mac text)",
                       "convert the line ends to '\\n' or '\\r\\n'", {file, lineNo, 0});
    if (!trim(l).empty()) lines_.push_back({l, lineNo});
  }
  std::vector<std::size_t> content;  // indices into `lines` of non-comment lines
  for (std::size_t i = 0; i < lines_.size(); ++i)
    if (!isComment(trim(lines_[i].text))) content.push_back(i);
  if (content.empty())
    throw InputError("header", lineNo == 0 ? "the file is empty" : "no header or data lines (only comments or blank lines)",
                     "the file needs a header line naming the columns and one row per sample", {file, lineNo, 0});

  std::vector<Mode> modes;
  switch (mapping.delimiter) {
    case Delimiter::kComma: modes = {{',', false}}; break;
    case Delimiter::kSemicolon: modes = {{';', false}}; break;
    case Delimiter::kTab: modes = {{'\t', false}}; break;
    case Delimiter::kWhitespace: modes = {{0, false}, {0, true}}; break;
    case Delimiter::kAuto: modes = {{'\t', false}, {';', false}, {',', false}, {0, false}, {0, true}}; break;
  }
  struct Candidate {
    Mode mode;
    std::size_t priority = 0;
    bool decimalComma = false;
    std::size_t count = 0;
    std::ptrdiff_t header = -1, units = -1, firstData = -1;
  };
  std::optional<Candidate> best;
  std::vector<Cell> cells;
  for (std::size_t m = 0; m < modes.size(); ++m) {
    const Mode& mode = modes[m];
    Candidate c;
    c.mode = mode;
    c.priority = m;
    c.decimalComma = mapping.decimal == DecimalMark::kComma || (mapping.decimal == DecimalMark::kAuto && mode.delim != ',');
    std::vector<std::size_t> count(content.size());
    std::vector<char> values(content.size());  // a data line: at least half of its cells are values
    std::map<std::size_t, std::size_t> lines;
    for (std::size_t k = 0; k < content.size(); ++k) {
      splitLine(lines_[content[k]].text, mode, false, cells);
      count[k] = cells.size();
      std::size_t v = 0;
      for (const auto& cell : cells) v += valueLike(cell.text, c.decimalComma);
      values[k] = cells.size() >= 2 && v >= 1 && 2 * v >= cells.size();
      if (values[k]) ++lines[cells.size()];
    }
    // The column count of most data lines.
    std::size_t most = 0;
    for (const auto& [n, times] : lines)
      if (times > most) {
        most = times;
        c.count = n;
      }
    if (most == 0) continue;
    for (std::size_t k = 0; k < content.size(); ++k)
      if (values[k] && count[k] == c.count) {
        c.firstData = static_cast<std::ptrdiff_t>(k);
        break;
      }
    auto headerCount = [&](std::size_t k) {
      splitLine(lines_[content[k]].text, mode, true, cells);
      return cells.size();
    };
    if (c.firstData >= 1) {
      const auto before = static_cast<std::size_t>(c.firstData - 1);
      bool unitsLine = false;
      if (before >= 1 && !values[before] && count[before] == c.count && headerCount(before - 1) == c.count &&
          !values[before - 1]) {
        splitLine(lines_[content[before]].text, mode, false, cells);
        unitsLine = std::all_of(cells.begin(), cells.end(), [](const Cell& x) { return unitLike(x.text); });
      }
      if (unitsLine) {
        c.header = static_cast<std::ptrdiff_t>(before - 1);
        c.units = static_cast<std::ptrdiff_t>(before);
      } else {
        for (std::ptrdiff_t k = c.firstData - 1; k >= 0; --k)
          if (!values[static_cast<std::size_t>(k)] && headerCount(static_cast<std::size_t>(k)) == c.count) {
            c.header = k;
            break;
          }
      }
    }
    // A header first, then the delimiter order (tab, ';', ',', blanks): a
    // file with a real delimiter can also split at blanks inside its cells.
    auto rank = [](const Candidate& x) { return std::make_pair(x.header >= 0, -static_cast<int>(x.priority)); };
    if (!best || rank(c) > rank(*best)) best = c;
  }
  if (!best)
    throw InputError("delimiter",
                     "no line splits into two or more numeric cells at ',', ';', tabs or blanks" +
                         std::string(mapping.delimiter == Delimiter::kAuto ? "" : " (the delimiter the mapping names)"),
                     "the file must be a table of numbers under a header line; if it uses another delimiter, "
                     "it cannot be read as delimited text",
                     {file, lines_[content.front()].line, 0});
  const Candidate& c = *best;
  if (c.header < 0)
    throw InputError("header",
                     "no header line naming the columns before the first data row (" + describe(c.mode) +
                         " separated, " + std::to_string(c.count) + " columns)",
                     "add a header line such as `time,depth [m],pitch [deg]` above the rows",
                     {file, lines_[content[static_cast<std::size_t>(c.firstData)]].line, 1});
  if (c.count > kMaxColumns)
    throw InputError("header", "more than " + std::to_string(kMaxColumns) + " columns", "this is not a log table",
                     {file, lines_[content[static_cast<std::size_t>(c.header)]].line, 1});
  Layout L;
  L.mode = c.mode;
  L.decimalComma = c.decimalComma;
  const HeadLine& h = lines_[content[static_cast<std::size_t>(c.header)]];
  L.headerLine = h.line;
  L.dataFrom = (c.units >= 0 ? lines_[content[static_cast<std::size_t>(c.units)]].line : h.line) + 1;
  for (std::size_t i = 0; i < lines_.size() && lines_[i].line < h.line; ++i)
    L.preamble.push_back(preambleEntry(trim(lines_[i].text)));
  std::string_view headerText = h.text;
  std::size_t bom = 0;
  if (h.line == 1 && headerText.substr(0, 3) == "\xEF\xBB\xBF") bom = 3;
  splitLine(headerText.substr(bom), c.mode, true, cells);
  for (const auto& cell : cells) {
    L.fields.push_back(parseHeaderField(cell.text));
    L.fieldColumn.push_back(static_cast<long>(cell.offset + bom) + 1);
  }
  // Columns that hold only text in the head's data lines (a status word, a
  // mode name) are not numbers; the planner leaves them out.
  L.textColumn.assign(L.fields.size(), 0);
  {
    std::vector<std::size_t> numeric(L.fields.size()), text(L.fields.size());
    for (std::size_t k = static_cast<std::size_t>(c.firstData); k < content.size(); ++k) {
      splitLine(lines_[content[k]].text, c.mode, false, cells);
      if (cells.size() != L.fields.size()) continue;
      for (std::size_t j = 0; j < cells.size(); ++j) {
        const std::string_view u = unquoted(cells[j].text);
        if (isMissingSpelling(u)) continue;
        (valueLike(u, c.decimalComma) ? numeric : text)[j]++;
      }
    }
    for (std::size_t j = 0; j < L.fields.size(); ++j) L.textColumn[j] = text[j] > 0 && numeric[j] == 0;
  }
  if (c.units >= 0) {
    splitLine(lines_[content[static_cast<std::size_t>(c.units)]].text, c.mode, false, cells);
    for (std::size_t k = 0; k < cells.size() && k < L.fields.size(); ++k)
      if (L.fields[k].unit.empty()) L.fields[k].unit = stripBrackets(cells[k].text);
  }
  return L;
}

// How each header cell is used.
struct Plan {
  static constexpr int kIgnore = -1, kTime = -2, kDate = -3;
  std::vector<int> target;  // per field: table column index or one of the above
  std::size_t timeField = 0;
  std::optional<std::size_t> dateField;
  TimeFormat format = TimeFormat::kAuto;
  double timeScale = 1.0;  // numeric time unit -> s
  bool epochHint = false;  // the time unit says "epoch/timestamp"
  LogTable table;          // columns without values
};

bool isTimeHint(const std::string& u, bool& epoch) {
  const std::string l = lower(trim(u));
  if (l == "timestamp" || l == "epoch" || l == "unix" || l == "posix" || l == "s since 1970") {
    epoch = true;
    return true;
  }
  return l == "utc" || l == "gmt" || l == "z" || l == "local" || l == "lt" || l == "iso" || l == "iso8601" ||
         l == "iso 8601" || l.find("yyyy") != std::string::npos || l.find("hh:mm") != std::string::npos;
}

std::string fieldList(const std::vector<HeaderField>& fields) {
  std::string s;
  for (std::size_t i = 0; i < fields.size() && i < 30; ++i)
    s += (s.empty() ? "" : ", ") + printableText(fields[i].text, 30, true);
  if (fields.size() > 30) s += ", ...";
  return s;
}

Plan planColumns(const Layout& L, const ColumnMapping& m, const std::string& file, const ReadOptions& options,
                 ReadReport& report) {
  Plan p;
  p.table.file = file;
  p.target.assign(L.fields.size(), Plan::kIgnore);
  auto where = [&](std::size_t k) { return InputLocation{file, L.headerLine, L.fieldColumn[k]}; };
  auto note = [&](ReadProblemKind kind, std::size_t k, std::string column, std::string what, std::string fix) {
    ReadProblem q;
    q.kind = kind;
    q.where = where(k);
    q.column = std::move(column);
    q.problem = std::move(what);
    q.fix = std::move(fix);
    report.add(std::move(q), options.max_problems_per_kind);
  };

  std::optional<std::size_t> timeField;
  if (!m.time.column.empty()) {
    for (std::size_t k = 0; k < L.fields.size() && !timeField; ++k)
      if (ColumnMapping::matches(m.time.column, L.fields[k])) timeField = k;
    if (!timeField)
      throw InputError("time", "the mapping's time column '" + m.time.column + "' is not in the header (" +
                                   fieldList(L.fields) + ")",
                       "correct \"time\": {\"column\": ...} in the column mapping", {file, L.headerLine, 1});
  } else {
    auto mappedAway = [&](std::size_t k) { return m.ruleFor(L.fields[k]) != nullptr; };
    for (std::size_t k = 0; k < L.fields.size() && !timeField; ++k)
      if (L.fields[k].key == "time" && !mappedAway(k)) timeField = k;
    for (std::size_t k = 0; k < L.fields.size() && !timeField; ++k)
      if (auto a = findChannelAlias(L.fields[k].key); a && a->channel == "time" && !mappedAway(k)) timeField = k;
    for (std::size_t k = 0; k < L.fields.size() && !timeField; ++k)
      if (auto a = findChannelAlias(L.fields[k].key); a && a->channel == "date" && !mappedAway(k)) timeField = k;
  }
  if (!timeField)
    throw InputError("time",
                     "no time column: none of the header cells (" + fieldList(L.fields) +
                         ") is a time name such as time, timestamp, datetime, utc or m_present_time",
                     "name the time column in a column mapping (\"time\": {\"column\": \"...\"}) or rename it 'time'",
                     {file, L.headerLine, 1});
  p.timeField = *timeField;
  p.target[p.timeField] = Plan::kTime;
  if (!m.time.date_column.empty()) {
    for (std::size_t k = 0; k < L.fields.size() && !p.dateField; ++k)
      if (k != p.timeField && ColumnMapping::matches(m.time.date_column, L.fields[k])) p.dateField = k;
    if (!p.dateField)
      throw InputError("time", "the mapping's date column '" + m.time.date_column + "' is not in the header (" +
                                   fieldList(L.fields) + ")",
                       "correct \"time\": {\"date_column\": ...} in the column mapping", {file, L.headerLine, 1});
  } else {
    for (std::size_t k = 0; k < L.fields.size() && !p.dateField; ++k)
      if (auto a = findChannelAlias(L.fields[k].key); k != p.timeField && a && a->channel == "date" && !m.ruleFor(L.fields[k]))
        p.dateField = k;
  }
  if (p.dateField) p.target[*p.dateField] = Plan::kDate;
  p.format = m.time.format;

  // The unit of a numeric time.
  {
    const HeaderField& f = L.fields[p.timeField];
    std::string unit = m.time.unit.empty() ? f.unit : m.time.unit;
    if (unit.empty())
      if (auto a = findChannelAlias(f.key)) unit = std::string(a->unit);
    bool epoch = false;
    if (!unit.empty()) {
      if (auto conv = unitConversion(normaliseUnitSpelling(unit), "s")) {
        p.timeScale = conv->scale;
      } else if (isTimeHint(unit, epoch)) {
        p.epochHint = epoch;
      } else {
        throw InputError(f.text, "unit [" + unit + "] of the time column is not a time unit",
                         "write the time in s, ms, min or h, as ISO 8601 or as dd.mm.yyyy hh:mm:ss",
                         where(p.timeField));
      }
    }
  }

  std::unordered_set<std::string> used;
  for (std::size_t k = 0; k < L.fields.size(); ++k) {
    if (p.target[k] != Plan::kIgnore) continue;
    const HeaderField& f = L.fields[k];
    TableColumn col;
    col.source_name = f.text;
    col.where = where(k);
    std::string unit = f.unit;
    if (const ColumnRule* rule = m.ruleFor(f)) {
      if (rule->ignore) continue;
      col.name = rule->channel;
      if (!rule->unit.empty()) unit = rule->unit;
      col.scale = rule->scale;
      col.offset = rule->offset;
      if (unit.empty())
        if (auto a = findChannelAlias(f.key); a && a->channel == rule->channel) unit = std::string(a->unit);
    } else if (L.textColumn[k]) {
      note(ReadProblemKind::kColumnIgnored, k, "",
           "column '" + printableText(f.text, 40, true) + "' holds text, not numbers; its values are ignored",
           "map it in the column mapping with \"ignore\": true to silence this note");
      continue;
    } else if (f.key.empty()) {
      note(ReadProblemKind::kColumnIgnored, k, "",
           "header cell " + std::to_string(k + 1) + " has no name; its values are ignored",
           "name the column or remove it (a trailing delimiter makes an empty column)");
      continue;
    } else if (auto a = findChannelAlias(f.key); a && a->channel != "time" && a->channel != "date") {
      col.name = std::string(a->channel);
      if (unit.empty()) unit = std::string(a->unit);
    } else {
      col.name = safeChannelName(f.key);
    }
    if (used.count(col.name)) {
      std::string renamed;
      for (int s = 2;; ++s) {
        renamed = col.name + "_" + std::to_string(s);
        if (!used.count(renamed)) break;
      }
      note(ReadProblemKind::kDuplicateColumn, k, col.name,
           "a second column maps to '" + col.name + "' ('" + printableText(f.text, 40, true) + "'); it is named '" + renamed + "'",
           "map one of them to another channel in the column mapping");
      col.name = renamed;
    }
    used.insert(col.name);
    col.source_unit = unit;
    col.unit = normaliseUnitSpelling(unit);
    p.target[k] = static_cast<int>(p.table.columns.size());
    p.table.columns.push_back(std::move(col));
  }
  return p;
}

class TextTableReader {
 public:
  TextTableReader(std::string file, const ColumnMapping& m, const ReadOptions& o, ReadReport& r)
      : file_(std::move(file)), map_(m), opt_(o), rep_(r) {}

  // Sniffs and plans from `head`; throws InputError when the layout is not usable.
  void prepare(std::string_view head, bool complete) {
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
  void setSizeHint(std::uint64_t n) { sizeHint_ = n; }

  bool line(std::string_view text, LineFlag flag);
  LogTable finish();
  const Layout& layout() const { return layout_; }
  const Plan& plan() const { return plan_; }

 private:
  void problem(ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix) {
    ReadProblem p;
    p.kind = kind;
    p.where = {file_, line_, column};
    p.column = std::move(channel);
    p.problem = std::move(what);
    p.fix = std::move(fix);
    rep_.add(std::move(p), opt_.max_problems_per_kind);
  }
  void skip(ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix) {
    ++rep_.rows_skipped;
    problem(kind, column, std::move(channel), std::move(what), std::move(fix));
  }
  bool parseTime(std::string_view cell, std::string_view dateCell, double& t);
  void detectFormat(std::string_view cell);

  std::string file_;
  const ColumnMapping& map_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  std::uint64_t sizeHint_ = 0;
  std::size_t expectedRows_ = 0;
  Layout layout_;
  Plan plan_;
  std::size_t nFields_ = 0;
  long long line_ = 0;
  std::vector<Cell> cells_;
  std::vector<double> row_;
  bool zoneNoted_ = false;
  double todDay_ = 0.0, lastTod_ = -1.0;
};

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
         "'" + printableText(trim(bad.text)) + "' is not " +
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
             "'" + printableText(trim(cells_[c].text)) + "' is not a number; row skipped",
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

std::string formatLabel(const Layout& L) {
  return "delimited text (" + describe(L.mode) + " separated" + (L.decimalComma && L.mode.delim != ',' ? ", decimal comma accepted" : "") + ")";
}

template <class F>
auto guardMemory(const std::string& name, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw InputError("log", "not enough memory to hold this log", "split the file or use a larger machine", {name, 0, 0});
  }
}

// One file -> a tidied table. `report` is not reset.
LogTable readTable(const std::filesystem::path& path, const ColumnMapping& m, const ReadOptions& o, ReadReport& r,
                   std::string& format) {
  const std::string name = path.string();
  BlockFile file(path);
  const std::string head = readFirstBytes(path, kHeadBytes);
  TextTableReader reader(name, m, o, r);
  reader.setSizeHint(file.size());
  reader.prepare(head, file.size() <= kHeadBytes);
  format = formatLabel(reader.layout());
  forEachLine(name, file.size(), FilePull{&file}, o, [&](std::string_view l, LineFlag f) { return reader.line(l, f); });
  LogTable t = reader.finish();
  tidyTable(t, o, r);
  return t;
}

}  // namespace

MissionLog readDelimitedText(const std::filesystem::path& path, const ColumnMapping& mapping,
                             const ReadOptions& options, ReadReport& report) {
  report = ReadReport{};
  report.file = path.string();
  return guardMemory(report.file, [&] {
    LogTable t = readTable(path, mapping, options, report, report.format);
    return finishTable(std::move(t), report, false);
  });
}

MissionLog parseDelimitedText(std::string_view text, const std::string& sourceName, const ColumnMapping& mapping,
                              const ReadOptions& options, ReadReport& report) {
  report = ReadReport{};
  report.file = sourceName;
  return guardMemory(sourceName, [&] {
    TextTableReader reader(sourceName, mapping, options, report);
    reader.setSizeHint(text.size());
    reader.prepare(text.substr(0, kHeadBytes), text.size() <= kHeadBytes);
    report.format = formatLabel(reader.layout());
    forEachLine(sourceName, text.size(), MemoryPull{text}, options,
                [&](std::string_view l, LineFlag f) { return reader.line(l, f); });
    LogTable t = reader.finish();
    tidyTable(t, options, report);
    return finishTable(std::move(t), report, false);
  });
}

MissionLog readMerged(const std::vector<std::filesystem::path>& paths, const ColumnMapping& mapping,
                      const ReadOptions& options, ReadReport& report) {
  report = ReadReport{};
  if (paths.empty())
    throw InputError("log", "no files to merge", "give the mission's text files (depth, misc, navigation, velocity ...)");
  std::vector<std::uint64_t> sizes;
  std::uint64_t total = 0;
  for (const auto& p : paths) {
    std::error_code ec;
    const auto s = std::filesystem::file_size(p, ec);
    sizes.push_back(ec ? 0 : s);
    total += ec ? 0 : s;
  }
  std::vector<LogTable> tables;
  std::uint64_t done = 0;
  std::string names;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    ReadOptions o = options;
    if (options.progress) {
      const double a = total ? static_cast<double>(done) / static_cast<double>(total) : 0.0;
      const double b = total ? static_cast<double>(done + sizes[i]) / static_cast<double>(total) : 1.0;
      o.progress = [&options, a, b](double f) { return options.progress(a + (b - a) * f); };
    }
    ReadReport r;
    std::string format;
    LogTable t = guardMemory(paths[i].string(), [&] { return readTable(paths[i], mapping, o, r, format); });
    t.tag = safeChannelName(normaliseChannelKey(paths[i].stem().string()));
    tables.push_back(std::move(t));
    done += sizes[i];
    names += (names.empty() ? "" : "; ") + paths[i].string();
    report.lines += r.lines;
    report.data_lines += r.data_lines;
    report.rows_skipped += r.rows_skipped;
    report.rows_merged += r.rows_merged;
    report.cells_blanked += r.cells_blanked;
    for (std::size_t k = 0; k < r.counts.size(); ++k) {
      long long kept = 0;
      for (const auto& p : report.problems) kept += static_cast<std::size_t>(p.kind) == k;
      for (const auto& p : r.problems)
        if (static_cast<std::size_t>(p.kind) == k && kept < static_cast<long long>(options.max_problems_per_kind)) {
          report.problems.push_back(p);
          ++kept;
        }
      report.counts[k] += r.counts[k];
    }
  }
  report.file = names;
  report.format = "delimited text, " + std::to_string(paths.size()) + " files merged";
  return guardMemory(names, [&] {
    LogTable merged = mergeTables(std::move(tables), MergeNames::kRename, options, report);
    merged.metadata.push_back({"source_files", names});
    return finishTable(std::move(merged), report, false);
  });
}

bool DelimitedTextReader::canRead(const std::filesystem::path& path, std::string_view head) const {
  try {
    ReadReport scratch;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    const bool complete = !ec && size <= head.size();
    const Layout L = sniffLayout(head, complete, mapping_, path.string());
    planColumns(L, mapping_, path.string(), ReadOptions{}, scratch);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

MissionLog DelimitedTextReader::read(const std::filesystem::path& path, const ReadOptions& options,
                                     ReadReport& report) const {
  return readDelimitedText(path, mapping_, options, report);
}

MissionLog DelimitedTextReader::readMerged(const std::vector<std::filesystem::path>& paths,
                                           const ReadOptions& options, ReadReport& report) const {
  return auv::readMerged(paths, mapping_, options, report);
}

namespace {
ColumnMapping suggestMapping(std::string_view head, bool complete, const std::string& sourceName) {
  ColumnMapping none;
  const Layout L = sniffLayout(head, complete, none, sourceName);
  ReadReport scratch;
  const Plan p = planColumns(L, none, sourceName, ReadOptions{}, scratch);
  ColumnMapping m;
  switch (L.mode.delim) {
    case ',': m.delimiter = Delimiter::kComma; break;
    case ';': m.delimiter = Delimiter::kSemicolon; break;
    case '\t': m.delimiter = Delimiter::kTab; break;
    default: m.delimiter = Delimiter::kWhitespace; break;
  }
  m.decimal = L.decimalComma ? DecimalMark::kComma : DecimalMark::kPoint;
  if (m.delimiter == Delimiter::kComma) m.decimal = DecimalMark::kPoint;
  m.time.column = L.fields[p.timeField].text;
  if (p.dateField) m.time.date_column = L.fields[*p.dateField].text;
  if (!L.fields[p.timeField].unit.empty() && unitConversion(normaliseUnitSpelling(L.fields[p.timeField].unit), "s"))
    m.time.unit = L.fields[p.timeField].unit;
  for (std::size_t k = 0; k < L.fields.size(); ++k) {
    const int target = p.target[k];
    if (target == Plan::kTime || target == Plan::kDate) continue;
    ColumnRule r;
    r.header = L.fields[k].text;
    if (target < 0) {
      r.ignore = true;
    } else {
      const TableColumn& c = p.table.columns[static_cast<std::size_t>(target)];
      r.channel = c.name;
      r.unit = c.source_unit;
      if (r.unit.empty()) r.unit = std::string(canonicalUnitFor(c.name));
    }
    m.columns.push_back(std::move(r));
  }
  return m;
}
}  // namespace

ColumnMapping suggestColumnMapping(std::string_view head, const std::string& sourceName) {
  return suggestMapping(head, true, sourceName);
}

ColumnMapping suggestColumnMapping(const std::filesystem::path& path) {
  const std::string head = readFirstBytes(path, kHeadBytes);
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return suggestMapping(head, !ec && size <= head.size(), path.string());
}

}  // namespace auv
