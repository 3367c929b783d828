// The delimited-text reader works in two passes over the start of the file and
// one over all of it: the layout (delimiter, header line, units line, decimal
// mark) is decided on up to 500 lines from the head (detail/delimited_layout.h),
// the columns are planned from the header and the mapping
// (detail/delimited_column_plan.h), then every line is read in blocks
// (detail/text_table_reader.h).
#include "missionlog/delimited_text_reader.h"

#include "common/input_error.h"
#include "missionlog/channel_aliases.h"
#include "missionlog/detail/delimited_column_plan.h"
#include "missionlog/detail/delimited_layout.h"
#include "missionlog/detail/memory_guard.h"
#include "missionlog/detail/text_table_reader.h"
#include "missionlog/log_table.h"
#include "missionlog/text_lines.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"

namespace auv {
namespace {

using detail::Layout;
using detail::Plan;
using detail::TextTableReader;

constexpr std::size_t kHeadBytes = 256 * 1024;

std::string formatLabel(const Layout& L) {
  return "delimited text (" + detail::describe(L.mode) + " separated" + (L.decimalComma && L.mode.delim != ',' ? ", decimal comma accepted" : "") + ")";
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
  return detail::guardMemory(report.file, [&] {
    LogTable t = readTable(path, mapping, options, report, report.format);
    return finishTable(std::move(t), report, false);
  });
}

MissionLog parseDelimitedText(std::string_view text, const std::string& sourceName, const ColumnMapping& mapping,
                              const ReadOptions& options, ReadReport& report) {
  report = ReadReport{};
  report.file = sourceName;
  return detail::guardMemory(sourceName, [&] {
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
    LogTable t = detail::guardMemory(paths[i].string(), [&] { return readTable(paths[i], mapping, o, r, format); });
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
  return detail::guardMemory(names, [&] {
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
    const Layout L = detail::sniffLayout(head, complete, mapping_, path.string());
    detail::planColumns(L, mapping_, path.string(), ReadOptions{}, scratch);
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
  const Layout L = detail::sniffLayout(head, complete, none, sourceName);
  ReadReport scratch;
  const Plan p = detail::planColumns(L, none, sourceName, ReadOptions{}, scratch);
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
