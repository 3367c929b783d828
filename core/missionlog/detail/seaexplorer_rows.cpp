#include "missionlog/detail/seaexplorer_rows.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_set>
#include <vector>

#include "common/input_error.h"
#include "missionlog/decimal_parse.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/detail/seaexplorer_columns.h"
#include "missionlog/iso8601.h"
#include "missionlog/time_text.h"

namespace auv::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool digits(std::string_view s, std::size_t at, std::size_t n, int& out) {
  if (at + n > s.size()) return false;
  out = 0;
  for (std::size_t i = at; i < at + n; ++i) {
    if (!isDigit(s[i])) return false;
    out = out * 10 + (s[i] - '0');
  }
  return true;
}

// Splits at ';' into `cells`; one empty cell after a final ';' is dropped.
void splitCells(std::string_view line, std::vector<std::string_view>& cells) {
  cells.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t semi = line.find(';', start);
    if (semi == std::string_view::npos) {
      if (start < line.size()) cells.push_back(line.substr(start));
      break;
    }
    cells.push_back(line.substr(start, semi - start));
    start = semi + 1;
  }
}

struct Column {
  SeaExplorerColumn rule;
  std::size_t out = 0;  // index into the table's columns
  bool imported = false;
};

class TableParser {
 public:
  TableParser(const std::string& file, const SeaExplorerName& name, const ReadOptions& o, ReadReport& r)
      : file_(file), name_(name), opt_(o), rep_(r) {}
  void header(std::string_view line, long lineNo);
  void row(std::string_view line, long lineNo, bool cutShort);
  LogTable finish();

 private:
  void skip(ReadProblemKind kind, long lineNo, long column, std::string channel, std::string what, std::string fix) {
    ++rep_.rows_skipped;
    ++rep_.data_lines;
    reportProblem(rep_, opt_, kind, {file_, lineNo, column}, std::move(channel), std::move(what), std::move(fix));
  }

  const std::string& file_;
  const SeaExplorerName& name_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  LogTable t_;
  std::vector<Column> cols_;
  std::size_t timeCol_ = 0, navStateCol_ = SIZE_MAX, latCol_ = SIZE_MAX, lonCol_ = SIZE_MAX;
  std::vector<std::string_view> cells_;
  std::vector<double> row_;
  double prevLat_ = kNaN, prevLon_ = kNaN;
};

void TableParser::header(std::string_view line, long lineNo) {
  splitCells(line, cells_);
  if (cells_.size() < 2 || line.find(';') == std::string_view::npos)
    throw InputError("header", "the first line is not a `;`-separated SeaExplorer header",
                     "give a SeaExplorer *.gli.sub.N(.gz) or *.pld1.raw.N(.gz) file as the glider wrote it",
                     {file_, lineNo, 0});
  bool haveTime = false;
  std::unordered_set<std::string> taken;
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    Column c;
    c.rule = seaExplorerColumn(cells_[k]);
    if (c.rule.time) {
      if (!haveTime) timeCol_ = k;
      haveTime = true;
      cols_.push_back(c);
      continue;
    }
    if (!c.rule.channel.empty()) {
      std::string name = c.rule.channel;
      for (int s = 2; taken.count(name); ++s) name = c.rule.channel + "_" + std::to_string(s);
      if (name != c.rule.channel)
        reportProblem(rep_, opt_, ReadProblemKind::kDuplicateColumn, {file_, lineNo, static_cast<long>(k + 1)},
                      c.rule.channel,
                      "column " + quotedCell(cells_[k]) + " is a second '" + c.rule.channel + "'; named '" + name + "'",
                      "check which sensor this column holds");
      taken.insert(name);
      TableColumn tc;
      tc.name = name;
      tc.source_name = std::string(trim(cells_[k]));
      tc.unit = c.rule.unit;
      tc.source_unit = c.rule.unit;
      tc.where = {file_, lineNo, static_cast<long>(k + 1)};
      c.out = t_.columns.size();
      c.imported = true;
      t_.columns.push_back(std::move(tc));
      if (c.rule.gps) (c.rule.channel == "gps_lat" ? latCol_ : lonCol_) = k;
      if (c.rule.channel == "nav_state") navStateCol_ = k;
    }
    cols_.push_back(c);
  }
  if (!haveTime)
    throw InputError("header",
                     "no time column (Timestamp or PLD_REALTIMECLOCK) in the header " +
                         quotedCell(line.substr(0, std::min<std::size_t>(line.size(), 60))),
                     "give a SeaExplorer raw file as the glider wrote it", {file_, lineNo, 0});
  row_.assign(t_.columns.size(), kNaN);
}

void TableParser::row(std::string_view line, long lineNo, bool cutShort) {
  if (trim(line).empty()) return;
  if (cutShort) {
    skip(ReadProblemKind::kTruncatedLine, lineNo, 0, "", "the last line is cut short (the file ends inside it); row skipped",
         "copy the file again from the glider");
    return;
  }
  splitCells(line, cells_);
  if (cells_.size() != cols_.size()) {
    skip(ReadProblemKind::kWrongCellCount, lineNo, 0, "",
         std::to_string(cells_.size()) + " cells where the header has " + std::to_string(cols_.size()) + "; row skipped",
         "check the file for damage");
    return;
  }
  double t = 0;
  const std::string_view tc = trim(cells_[timeCol_]);
  if (tc.empty()) {
    skip(ReadProblemKind::kMissingTime, lineNo, 1, "time", "no time stamp; row skipped", "every row needs a time stamp");
    return;
  }
  if (!parseSeaExplorerTime(tc, t)) {
    skip(ReadProblemKind::kNotANumber, lineNo, 1, "time",
         quotedCell(tc) + " is not a time (dd/mm/yyyy HH:MM:SS[.fff]); row skipped", "correct the time stamp");
    return;
  }
  bool sampled = false;
  double navState = kNaN, lat = kNaN, lon = kNaN;
  for (std::size_t k = 0; k < cols_.size(); ++k) {
    const Column& c = cols_[k];
    if (!c.imported) continue;
    const std::string_view cell = trim(cells_[k]);
    double v = kNaN;
    if (!cell.empty()) {
      const char* end = cell.data() + cell.size();
      const char* p = parseDecimal(cell.data(), end, v);
      if (p != end) {
        skip(ReadProblemKind::kNotANumber, lineNo, static_cast<long>(k + 1), t_.columns[c.out].name,
             quotedCell(cell) + " is not a number; row skipped", "correct or empty the cell");
        return;
      }
      sampled = true;
    }
    switch (c.rule.value) {
      case SeaExplorerValue::kAsRecorded: break;
      case SeaExplorerValue::kNmeaDegrees: v = nmeaToDegrees(v); break;
      case SeaExplorerValue::kNonNegative: v = v >= 0.0 ? v : kNaN; break;
      case SeaExplorerValue::kHeading360:
        if (std::isfinite(v)) v = std::fmod(std::fmod(v, 360.0) + 360.0, 360.0);
        break;
    }
    if (k == navStateCol_) navState = v;
    if (k == latCol_) lat = v;
    if (k == lonCol_) lon = v;
    row_[c.out] = v;
  }
  if (!sampled) return;  // only the payload's copy of the navigation
  // Lat/Lon repeat the last fix in every record; a new fix is a changed
  // position while the glider is at the surface (NavState 116).
  if (latCol_ != SIZE_MAX || lonCol_ != SIZE_MAX) {
    const bool changed = !(lat == prevLat_ && lon == prevLon_);
    const bool surface = navStateCol_ == SIZE_MAX || navState == 116.0;
    prevLat_ = lat;
    prevLon_ = lon;
    if (!(changed && surface)) {
      if (latCol_ != SIZE_MAX) row_[cols_[latCol_].out] = kNaN;
      if (lonCol_ != SIZE_MAX) row_[cols_[lonCol_].out] = kNaN;
    }
  }
  ++rep_.data_lines;
  t_.time.push_back(t);
  t_.row_where.push_back(lineNo);
  for (std::size_t j = 0; j < row_.size(); ++j) {
    t_.columns[j].values.push_back(row_[j]);
    row_[j] = kNaN;
  }
}

LogTable TableParser::finish() {
  t_.file = file_;
  t_.epoch = true;
  if (name_.stream == "gli" && name_.yo >= 0 && !t_.time.empty()) {
    TableColumn yo;
    yo.name = "yo_number";
    yo.source_name = "yo number (file name)";
    yo.unit = "1";
    yo.where = {file_, 0, 0};
    yo.values.assign(t_.time.size(), static_cast<double>(name_.yo));
    t_.columns.push_back(std::move(yo));
  }
  return std::move(t_);
}

}  // namespace

bool parseSeaExplorerTime(std::string_view s, double& out) {
  int d = 0, m = 0, y = 0, hh = 0, mm = 0, ss = 0;
  if (s.size() >= 19 && s[2] == '/' && s[5] == '/' && digits(s, 0, 2, d) && digits(s, 3, 2, m) &&
      digits(s, 6, 4, y) && (s[10] == ' ' || s[10] == 'T') && digits(s, 11, 2, hh) && s[13] == ':' &&
      digits(s, 14, 2, mm) && s[16] == ':' && digits(s, 17, 2, ss)) {
    double frac = 0.0;
    std::size_t at = 19;
    if (at < s.size() && s[at] == '.') {
      double scale = 0.1;
      ++at;
      const std::size_t first = at;
      for (; at < s.size() && isDigit(s[at]); ++at, scale *= 0.1) frac += (s[at] - '0') * scale;
      if (at == first) return false;
    }
    if (at != s.size() || hh > 23 || mm > 59 || ss > 60) return false;
    const auto days = civilDays(y, m, d);
    if (!days) return false;
    // Whole seconds and the fraction apart: the fraction as written in
    // decimal (".852") must come out as the nearest double to it.
    out = static_cast<double>(*days) * 86400.0 + hh * 3600.0 + mm * 60.0 + ss;
    if (frac != 0.0) {
      double f = 0;
      const auto r = std::from_chars(s.data() + 19, s.data() + s.size(), f);  // ".852" as one number
      out += r.ec == std::errc() ? f : frac;
    }
    return true;
  }
  if (auto v = parseIso8601(s)) {
    out = *v;
    return true;
  }
  if (auto v = parseDayMonthYear(s)) {
    out = *v;
    return true;
  }
  return false;
}

SeaExplorerName parseSeaExplorerName(std::string_view f) {
  SeaExplorerName n;
  if (f.size() > 3 && f.substr(f.size() - 3) == ".gz") f.remove_suffix(3);
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dot = f.find('.', start);
    parts.push_back(f.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  // glider . mission . stream . (sub|raw) . yo
  if (parts.size() != 5) return n;
  long yo = 0;
  const auto r = std::from_chars(parts[4].data(), parts[4].data() + parts[4].size(), yo);
  if (r.ec != std::errc() || r.ptr != parts[4].data() + parts[4].size()) return n;
  n.glider = std::string(parts[0]);
  n.mission = std::string(parts[1]);
  n.stream = lower(parts[2]);
  n.yo = yo;
  return n;
}

LogTable parseSeaExplorerTable(std::string_view text, bool complete, const std::string& file,
                               const SeaExplorerName& name, const ReadOptions& options, ReadReport& report) {
  TableParser p(file, name, options, report);
  bool haveHeader = false;
  long lineNo = 0;
  std::size_t at = 0;
  const std::size_t total = text.size();
  std::size_t nextProgress = options.block_bytes;
  while (at < total) {
    std::size_t nl = text.find('\n', at);
    const bool last = nl == std::string_view::npos;
    if (last) nl = total;
    std::string_view line = text.substr(at, nl - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++lineNo;
    ++report.lines;
    if (!haveHeader) {
      if (!trim(line).empty()) {
        p.header(line, lineNo);
        haveHeader = true;
      }
    } else {
      const long long before = report.data_lines, skippedBefore = report.rows_skipped;
      p.row(line, lineNo, last && !complete);
      if (last && complete && report.data_lines > before && report.rows_skipped == skippedBefore)
        reportProblem(report, options, ReadProblemKind::kNoFinalNewline, {file, lineNo, 0}, "",
                      "the last line has no line end; it was read", "nothing to do if the row is complete");
    }
    at = nl + 1;
    if (at >= nextProgress && options.progress) {
      nextProgress += options.block_bytes;
      if (!options.progress(0.5 + 0.4 * static_cast<double>(at) / static_cast<double>(total))) throw ReadCancelled(file);
    }
  }
  if (!haveHeader)
    throw InputError("header", "the file is empty (no header line)", "give a SeaExplorer raw file as the glider wrote it",
                     {file, 0, 0});
  return p.finish();
}

}  // namespace auv::detail
