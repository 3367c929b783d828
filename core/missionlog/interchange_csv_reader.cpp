// Reader of the interchange CSV: the `# key: value` preamble and the header
// (detail/interchange_header.h) are read line by line, the rows
// (detail/interchange_rows.h) a block at a time. Time order is repaired after
// the whole file is read (detail/time_order.h), with the same rule as the
// vendor readers.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/attitude_sanity.h"
#include "missionlog/detail/interchange_header.h"
#include "missionlog/detail/interchange_rows.h"
#include "missionlog/detail/line_cells.h"
#include "missionlog/detail/memory_guard.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/detail/time_order.h"
#include "missionlog/interchange_csv.h"
#include "missionlog/iso8601.h"
#include "missionlog/log_table.h"
#include "missionlog/text_lines.h"

namespace auv {
namespace {

using detail::trim;

class Parser {
 public:
  Parser(std::string file, const ReadOptions& o, ReadReport& r, std::uint64_t sizeHint)
      : file_(std::move(file)), opt_(o), rep_(r), size_hint_(sizeHint) {
    rep_.file = file_;
    rep_.format = "mission-log CSV v1";
  }

  // Complete lines: [b, e) with e[-1] == '\n'.
  void lines(const char* b, const char* e) {
    while (b < e && !rows_) {
      const char* nl = static_cast<const char*>(std::memchr(b, '\n', static_cast<std::size_t>(e - b)));
      ++line_;
      preambleLine(std::string_view(b, static_cast<std::size_t>(nl - b)));
      b = nl + 1;
    }
    if (b < e) rows_->lines(b, e);
  }

  // The last line of the file when it has no line end.
  void finalLine(const char* b, const char* e) {
    const std::string_view line(b, static_cast<std::size_t>(e - b));
    if (rows_) {
      rows_->finalLine(line);
      return;
    }
    ++line_;
    preambleLine(line);
  }

  // A line longer than the read block, already skipped by the driver.
  void overlongLine() {
    if (rows_) {
      rows_->overlongLine();
      return;
    }
    ++line_;  // could have been the header: nothing after it can be trusted
    throw InputError("header",
                     "line is longer than " + std::to_string(opt_.block_bytes) +
                         " bytes before the header (binary data or no line ends?)",
                     "the file must be text with '\\n' or '\\r\\n' line ends and a "
                     "`name [unit]` header",
                     {file_, line_, 0});
  }

  MissionLog finish();

 private:
  void preambleLine(std::string_view line);
  void checkAttitudeUnits(std::vector<detail::InterchangeColumn>& cols, std::vector<std::vector<double>>& data,
                          std::size_t timeCol);

  std::string file_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  std::uint64_t size_hint_;

  long long line_ = 0;  // up to the header; the row reader counts on from there
  long long header_line_ = 0;
  std::vector<MetadataEntry> meta_;
  std::optional<detail::InterchangeRowReader> rows_;  // set once the header is read
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
    meta_.push_back(detail::parseMetadataLine(t.substr(1)));
    return;
  }
  header_line_ = line_;
  rows_.emplace(file_, detail::parseInterchangeHeader(line, file_, line_, opt_, rep_), line_, size_hint_, opt_,
                rep_);
}

MissionLog Parser::finish() {
  if (!rows_)
    throw InputError("header",
                     line_ == 0 ? "the file is empty" : "no header line (only metadata or blank lines)",
                     "after the `# key: value` lines the file needs a header such as "
                     "`time [s],depth [m]` and one row per sample",
                     {file_, line_, 0});
  const long long lastLine = rows_->line();
  std::vector<detail::InterchangeColumn>& cols = rows_->header().columns;
  std::vector<std::vector<double>>& data = rows_->data();
  const std::size_t timeCol = rows_->header().time_column;
  if (rows_->rowLines().empty()) {
    std::string why = "no usable data rows";
    if (rep_.data_lines > 0)
      why += " (" + std::to_string(rep_.data_lines) + " data lines, all skipped; first: " +
             (rep_.problems.empty() ? std::string("?") : rep_.problems.front().text()) + ")";
    throw InputError("rows", why, "the file needs at least one row with a valid time",
                     {file_, lastLine, 0});
  }
  MissionLog log;
  log.metadata = std::move(meta_);
  // Conversions first, so that time order and duplicates are judged in seconds.
  for (std::size_t c = 0; c < cols.size(); ++c)
    if (!cols[c].conv.isIdentity() && !cols[c].ignored)
      for (double& v : data[c]) v = cols[c].conv.apply(v);
  checkAttitudeUnits(cols, data, timeCol);
  if (rows_->header().iso_time) {
    std::vector<double>& t = data[timeCol];
    std::optional<double> start = log.startEpochSeconds();
    if (!start) {
      start = *std::min_element(t.begin(), t.end());
      log.setMetadata("start", formatIso8601(*start, 3));
    }
    for (double& v : t) v -= *start;
  }

  // Every other column, ignored ones too (a repeated row merges them as well).
  LogTable table;
  table.file = file_;
  table.time = std::move(data[timeCol]);
  table.row_where = std::move(rows_->rowLines());
  for (std::size_t c = 0; c < cols.size(); ++c) {
    if (c == timeCol) continue;
    TableColumn col;
    col.name = cols[c].name;
    col.values = std::move(data[c]);
    table.columns.push_back(std::move(col));
  }
  detail::repairTimeOrder(table, opt_, rep_);
  detail::noteTimeGaps(table, opt_, rep_);

  log.time = std::move(table.time);
  for (std::size_t c = 0, k = 0; c < cols.size(); ++c) {
    if (c == timeCol) continue;
    TableColumn& col = table.columns[k++];
    if (cols[c].ignored) continue;
    LogChannel ch;
    ch.name = std::move(cols[c].name);
    ch.unit = std::move(cols[c].unit);
    ch.source_unit = std::move(cols[c].source_unit);
    ch.values = std::move(col.values);
    if (ch.values.capacity() > ch.values.size() + ch.values.size() / 4) ch.values.shrink_to_fit();
    log.channels.push_back(std::move(ch));
  }
  if (log.time.capacity() > log.time.size() + log.time.size() / 4) log.time.shrink_to_fit();
  rep_.rows_kept = static_cast<long long>(log.time.size());
  rep_.lines = lastLine;
  return log;
}

// Pitch and roll after conversion to degrees (detail/attitude_sanity.h, the
// rule the vendor readers use): mostly beyond +-90/180 deg is meaningless and
// refused (degrees under a [rad] header would give thousands of kg); a few
// beyond are blanked with a warning; a dived log whose attitude stays within
// +-1.6 "deg" is warned about as likely radians.
void Parser::checkAttitudeUnits(std::vector<detail::InterchangeColumn>& cols, std::vector<std::vector<double>>& data,
                                std::size_t timeCol) {
  double zmin = 0.0, zmax = 0.0;
  bool anyDepth = false;
  for (std::size_t c = 0; c < cols.size(); ++c) {
    if (c == timeCol || cols[c].ignored || cols[c].name != "depth") continue;
    for (double v : data[c])
      if (std::isfinite(v)) {
        zmin = anyDepth ? std::min(zmin, v) : v;
        zmax = anyDepth ? std::max(zmax, v) : v;
        anyDepth = true;
      }
  }
  for (std::size_t c = 0; c < cols.size(); ++c) {
    // The measured attitude the analysis uses; commands (pitch_cmd) and
    // model outputs are extra channels whose values the reader keeps as given.
    if (c == timeCol || cols[c].ignored || (cols[c].name != "pitch" && cols[c].name != "roll")) continue;
    const std::string base = cols[c].name;
    const detail::AttitudeCheck a = detail::checkAttitudeDeg(base, data[c]);
    if (a.limit_deg == 0.0) continue;
    const std::string declared = "[" + (cols[c].source_unit.empty() ? cols[c].unit : cols[c].source_unit) + "]";
    const bool declaredRad = !cols[c].conv.isIdentity();  // the only angle conversion is from radians
    const std::string other = declaredRad ? "deg" : "rad";
    if (a.beyond > 0) {
      const std::string what = std::to_string(a.beyond) + " of " + std::to_string(a.valid) + " values beyond +-" +
                               numberText(a.limit_deg - 0.5) + " deg (up to " + numberText(a.worst_deg) +
                               " deg read as " + declared + ")";
      const std::string fix = "if the column holds " + (other == "deg" ? std::string("degrees") : "radians") +
                              ", write `" + cols[c].name + " [" + other + "]` in the header (docs/formats/mission-log-csv.md)";
      if (a.mostlyBeyond()) {
        throw InputError(cols[c].name, what + ": the unit is wrong and the attitude meaningless", fix,
                         {file_, header_line_, 0});
      }
      rep_.cells_blanked += static_cast<long long>(a.beyond);
      detail::reportProblem(rep_, opt_, ReadProblemKind::kValueOutOfRange, {file_, header_line_, 0}, cols[c].name,
                            what + "; treated as not sampled", fix);
    } else if (!declaredRad && detail::looksLikeRadians(base, a, zmax - zmin)) {
      detail::reportProblem(rep_, opt_, ReadProblemKind::kUnitAssumed, {file_, header_line_, 0}, cols[c].name,
                            "all " + std::to_string(a.valid) + " values are within +-" + roundedText(a.max_abs_deg) +
                                " " + declared + " while the vehicle changed depth by " +
                                roundedText(zmax - zmin) + " m, which looks like radians",
                            "if the column holds radians, write `" + cols[c].name +
                                " [rad]` in the header (docs/formats/mission-log-csv.md)");
    }
  }
}

// The block loop shared by files and memory. Unlike forEachLine it hands the
// parser every complete line of a block at once, for the rows' fast path.
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
    std::vector<detail::Cell> cells;
    detail::splitAt(line, ',', cells);
    // Also claimed: a header of `name [unit]` cells with format channels but
    // no time-like column at all, so the refusal is this format's "no `time`
    // column" at file:line:column rather than "no reader recognises".
    bool allWellFormed = true, anyChannel = false, timeLike = false;
    for (const auto& c : cells) {
      const detail::HeaderCell h = detail::parseHeaderCell(c.text);
      if (h.name == "time" && h.well_formed) return true;
      allWellFormed = allWellFormed && h.well_formed && h.bracket;
      anyChannel = anyChannel || !canonicalUnitFor(h.name).empty();
      std::string lower(h.name);
      for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      timeLike = timeLike || lower.find("time") != std::string::npos || lower.find("date") != std::string::npos;
    }
    return allWellFormed && anyChannel && !timeLike;
  }
  return false;
}

MissionLog InterchangeCsvReader::read(const std::filesystem::path& path, const ReadOptions& options,
                                      ReadReport& report) const {
  return readInterchangeCsv(path, options, report);
}

MissionLog readInterchangeCsv(const std::filesystem::path& path, const ReadOptions& options,
                              ReadReport& report) {
  BlockFile file(path);
  return detail::guardMemory(file.name(),
                             [&] { return runParser(file.name(), file.size(), FilePull{&file}, options, report); });
}

MissionLog readInterchangeCsv(const std::filesystem::path& path) {
  ReadReport report;
  return readInterchangeCsv(path, ReadOptions{}, report);
}

MissionLog parseInterchangeCsv(std::string_view text, const std::string& sourceName,
                               const ReadOptions& options, ReadReport& report) {
  return detail::guardMemory(
      sourceName, [&] { return runParser(sourceName, text.size(), MemoryPull{text}, options, report); });
}

}  // namespace auv
