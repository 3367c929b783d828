#include "missionlog/detail/interchange_header.h"

#include <unordered_set>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/line_cells.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/log_table.h"

namespace auv::detail {
namespace {

constexpr std::size_t kMaxColumns = 100000;

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

}  // namespace

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

MetadataEntry parseMetadataLine(std::string_view body) {
  body = trim(body);
  const auto colon = body.find(':');
  if (colon == std::string_view::npos) return {std::string(), std::string(body)};
  return {std::string(trim(body.substr(0, colon))), std::string(trim(body.substr(colon + 1)))};
}

InterchangeHeader parseInterchangeHeader(std::string_view line, const std::string& file, long long lineNo,
                                         const ReadOptions& options, ReadReport& report) {
  const InputLocation here{file, lineNo, 1};
  auto problem = [&](ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix) {
    reportProblem(report, options, kind, {file, lineNo, column}, std::move(channel), std::move(what), std::move(fix));
  };
  if (line.find('\r') != std::string_view::npos)
    throw InputError("header", "lines end in a bare carriage return (classic Mac text)",
                     "convert the line ends to '\\n' or '\\r\\n'", here);
  std::vector<Cell> cells;
  splitAt(line, ',', cells);
  if (cells.size() > kMaxColumns)
    throw InputError("header", "more than " + std::to_string(kMaxColumns) + " columns",
                     "this is not a mission log header", here);
  InterchangeHeader h;
  h.columns.assign(cells.size(), InterchangeColumn{});
  std::unordered_set<std::string> seen;
  bool haveTime = false;
  std::string timeLike;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    InterchangeColumn& col = h.columns[c];
    const long at = static_cast<long>(cells[c].offset) + 1;
    const HeaderCell cell = parseHeaderCell(cells[c].text);
    std::string name = cell.name;
    const std::string& unit = cell.unit;
    const bool unitWritten = cell.bracket;
    if (!cell.well_formed) {
      const bool delimiter = cell.text.find(';') != std::string::npos || cell.text.find('\t') != std::string::npos;
      const std::string what = "header cell '" + printableText(cell.text, 60) + "' is not `name [unit]`" +
                               (delimiter ? " (this format is comma-separated; the file seems to use ';' or tabs)" : "");
      if (name == "time" || !canonicalUnitFor(name).empty())
        throw InputError(name, what, "write the column as `name [unit]`, columns separated by commas",
                         {file, lineNo, at});
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
      h.time_column = c;
      if (iequals(unit, "iso8601") || iequals(unit, "iso")) {
        h.iso_time = true;
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
                         {file, lineNo, at});
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
                     "write the column in one of: " + accepted, {file, lineNo, at});
  }
  if (!haveTime) {
    std::string why;
    if (cells.size() == 1 && (line.find(';') != std::string_view::npos ||
                              line.find('\t') != std::string_view::npos))
      why = "the header has a single cell: this format is comma-separated, the file seems to "
            "use ';' or tabs";
    else if (!timeLike.empty())
      why = "no column named exactly `time` (found '" + printableText(timeLike, 40) + "')";
    else
      why = "no `time` column in the header line '" + printableText(trim(line), 60) + "'";
    throw InputError("time", why,
                     "the first line after the `# key: value` metadata must be the header, "
                     "with a `time [s]` (seconds since `# start:`) or `time [iso8601]` column",
                     here);
  }
  return h;
}

}  // namespace auv::detail
