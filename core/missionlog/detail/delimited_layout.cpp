#include "missionlog/detail/delimited_layout.h"

#include <algorithm>
#include <map>
#include <optional>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/iso8601.h"
#include "missionlog/text_cells.h"
#include "missionlog/time_text.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"

namespace auv::detail {
namespace {

constexpr std::size_t kHeadLines = 500;
constexpr std::size_t kMaxColumns = 10000;

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

MetadataEntry preambleEntry(std::string_view t) {
  if (isComment(t)) t = trim(t.substr(t.front() == '/' ? 2 : 1));
  const auto colon = t.find(':');
  if (colon == std::string_view::npos || colon == 0 || colon > 40) return {std::string(), std::string(t)};
  return {std::string(trim(t.substr(0, colon))), std::string(trim(t.substr(colon + 1)))};
}

}  // namespace

bool isAbsoluteTimeText(std::string_view c) {
  double e = 0;
  bool zone = false;
  const char* end = c.data() + c.size();
  return (!c.empty() && parseIso8601Prefix(c.data(), end, e, zone) == end) || parseDayMonthYear(c) ||
         parseTimeOfDay(c) || parseDateOnly(c);
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

}  // namespace auv::detail

