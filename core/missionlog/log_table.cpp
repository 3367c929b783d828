#include "missionlog/log_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "missionlog/detail/attitude_sanity.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/detail/table_rows.h"
#include "missionlog/detail/time_order.h"
#include "missionlog/iso8601.h"
#include "missionlog/unit_conversion.h"

namespace auv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Absolute times outside 1900..2200 are damage (or wrong units), not a clock.
constexpr double kEpochMin = -2208988800.0;  // 1900-01-01T00:00:00Z
constexpr double kEpochMax = 7258118400.0;   // 2200-01-01T00:00:00Z

class TableTidier {
 public:
  TableTidier(LogTable& t, const ReadOptions& o, ReadReport& r) : t_(t), opt_(o), rep_(r) {}
  void run();

 private:
  InputLocation rowAt(std::size_t i) const { return detail::rowLocation(t_, i); }
  std::string rowPrefix(std::size_t i) const { return detail::rowPrefix(t_, i); }
  void problem(ReadProblemKind kind, InputLocation where, std::string column, std::string what,
               std::string fix) {
    detail::reportProblem(rep_, opt_, kind, std::move(where), std::move(column), std::move(what), std::move(fix));
  }
  void convertUnits();
  void checkPhysicalLimits(TableColumn& c);
  void dropRowsWithoutTime();

  LogTable& t_;
  const ReadOptions& opt_;
  ReadReport& rep_;
};

void TableTidier::convertUnits() {
  const std::size_t n = t_.time.size();
  for (auto& c : t_.columns) {
    if (!c.values.empty()) c.values.resize(n, kNaN);
    const std::string canonical(canonicalUnitFor(c.name));
    const std::string& target = canonical.empty() ? c.to_unit : canonical;
    UnitConversion conv;
    if (!target.empty() && c.unit != target) {
      if (c.unit.empty()) {
        if (!canonical.empty()) {
          std::string what = "no unit given; [" + canonical + "] (the format's unit for this channel) assumed";
          const std::string base(baseChannelName(c.name));
          if ((base == "pitch" || base == "roll" || base == "heading") && !c.values.empty()) {
            std::size_t valid = 0;
            double maxAbs = 0.0;
            for (double v : c.values)
              if (!std::isnan(v) && std::isfinite(v)) {
                ++valid;
                maxAbs = std::max(maxAbs, std::fabs(v * c.scale + c.offset));
              }
            if (valid >= 10 && maxAbs > 0.0 && maxAbs <= (base == "heading" ? 6.3 : 1.6))
              what += "; all " + std::to_string(valid) + " values are within +-" + numberText(maxAbs) +
                      ", which looks like radians";
          }
          problem(ReadProblemKind::kUnitAssumed, c.where, c.name, what,
                  "state the unit in the header or in the column mapping (e.g. `" + c.source_name + " [" +
                      canonical + "]`)");
        }
        c.unit = target.empty() ? c.unit : target;
      } else if (auto k = unitConversion(c.unit, target)) {
        conv = *k;
        c.unit = target;
      } else if (!canonical.empty()) {
        std::string accepted;
        for (const auto& u : unitsConvertibleTo(canonical)) accepted += (accepted.empty() ? "" : ", ") + u;
        throw InputError(c.source_name.empty() ? c.name : c.source_name,
                         "unit [" + (c.source_unit.empty() ? c.unit : c.source_unit) +
                             "] cannot be converted to [" + canonical + "], the unit of channel '" + c.name + "'",
                         "state the unit as one of: " + accepted + " (or map the column to another channel)",
                         c.where);
      }
      // An extra channel whose unit cannot reach `to_unit` keeps its own unit.
    }
    if (c.values.empty()) continue;
    std::size_t firstBad = n;
    long long bad = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double& v = c.values[i];
      if (std::isnan(v)) continue;
      if (!std::isfinite(v) || std::fabs(v) > opt_.max_abs_value) {
        if (bad < static_cast<long long>(opt_.max_problems_per_kind))
          problem(ReadProblemKind::kValueOutOfRange, rowAt(i), c.name,
                  rowPrefix(i) + "'" + numberText(v) + "' is infinite or beyond +-" + numberText(opt_.max_abs_value) +
                      " (a fill value or corruption); treated as not sampled",
                  "leave cells empty where nothing was sampled");
        else
          ++rep_.counts[static_cast<std::size_t>(ReadProblemKind::kValueOutOfRange)];
        if (firstBad == n) firstBad = i;
        ++bad;
        v = kNaN;
        continue;
      }
      v = conv.apply(v * c.scale + c.offset);
      if (!std::isfinite(v) || std::fabs(v) > opt_.max_abs_value) {  // huge after conversion: same rule
        ++rep_.counts[static_cast<std::size_t>(ReadProblemKind::kValueOutOfRange)];
        ++bad;
        v = kNaN;
      }
    }
    rep_.cells_blanked += bad;
    checkPhysicalLimits(c);
  }
}

// A pitch beyond +-90 deg or a roll beyond +-180 deg cannot be an attitude:
// almost always a column in degrees declared as radians (or the reverse).
void TableTidier::checkPhysicalLimits(TableColumn& c) {
  const std::string base(baseChannelName(c.name));
  const detail::AttitudeCheck a = detail::checkAttitudeDeg(base, c.values);
  const std::size_t bad = a.beyond, valid = a.valid, first = a.first_beyond;
  const double limit = a.limit_deg, worst = a.worst_deg;
  if (!bad) return;
  rep_.cells_blanked += static_cast<long long>(bad);
  std::string what = rowPrefix(first) + std::to_string(bad) + " of " + std::to_string(valid) + " values beyond +-" +
                     numberText(limit - 0.5) + " deg (up to " + numberText(worst) + " deg after converting from [" +
                     (c.source_unit.empty() ? std::string("assumed ") + c.unit : c.source_unit) +
                     "]); treated as not sampled";
  if (2 * bad > valid) what += ": the unit of this column is probably wrong";
  problem(ReadProblemKind::kValueOutOfRange, rowAt(first), c.name, what,
          "check the unit of '" + c.source_name + "' (rad or deg) in the header or the column mapping");
  rep_.counts[static_cast<std::size_t>(ReadProblemKind::kValueOutOfRange)] += static_cast<long long>(bad) - 1;
}

void TableTidier::dropRowsWithoutTime() {
  const std::size_t n = t_.time.size();
  std::vector<char> keep(n, 1);
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = t_.time[i];
    if (std::isnan(v)) {
      problem(ReadProblemKind::kMissingTime, rowAt(i), "time", rowPrefix(i) + "time is empty, NaN or a fill value; row skipped",
              "every row needs a time stamp");
    } else if (!std::isfinite(v) || std::fabs(v) > opt_.max_abs_value) {
      problem(ReadProblemKind::kValueOutOfRange, rowAt(i), "time",
              rowPrefix(i) + "time '" + numberText(v) + "' is infinite or beyond 1e30; row skipped", "correct the time stamp");
    } else if (t_.epoch && (v < kEpochMin || v > kEpochMax)) {
      problem(ReadProblemKind::kValueOutOfRange, rowAt(i), "time",
              rowPrefix(i) + "time " + numberText(v) + " s since 1970 is not between the years 1900 and 2200; row skipped",
              "correct the time stamp (or its units)");
    } else {
      continue;
    }
    keep[i] = 0;
    any = true;
    ++rep_.rows_skipped;
  }
  if (any) detail::keepRows(t_, keep);
}

void TableTidier::run() {
  if (t_.row_where.size() < t_.time.size()) t_.row_where.resize(t_.time.size(), 0);
  convertUnits();
  dropRowsWithoutTime();
  detail::repairTimeOrder(t_, opt_, rep_);
  detail::noteTimeGaps(t_, opt_, rep_);
}

}  // namespace

std::string numberText(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string roundedText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string printableText(std::string_view s, std::size_t max, bool keepUtf8) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < max; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if ((c >= 0x20 && c < 0x7f) || (keepUtf8 && c >= 0x80)) {
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

std::string toValidUtf8(std::string_view s) {
  bool valid = true;
  for (std::size_t i = 0; i < s.size() && valid;) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size() || (n == 2 && c < 0xC2)) {
      valid = false;
      break;
    }
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) valid = false;
    if (n == 3 && valid) {  // no overlong forms or surrogates
      const auto d = static_cast<unsigned char>(s[i + 1]);
      if ((c == 0xE0 && d < 0xA0) || (c == 0xED && d >= 0xA0)) valid = false;
    }
    if (n == 4 && valid) {
      const auto d = static_cast<unsigned char>(s[i + 1]);
      if (c > 0xF4 || (c == 0xF0 && d < 0x90) || (c == 0xF4 && d >= 0x90)) valid = false;
    }
    i += n;
  }
  if (valid) return std::string(s);
  std::string out;
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x80) {
      out += ch;
    } else {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

std::string safeChannelName(std::string_view name) {
  std::string out;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u == 0x7f || c == ',' || c == '[' || c == ']' || c == '"' || c == '#') ? '_' : c;
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '_')) out.pop_back();
  std::size_t lead = 0;
  while (lead < out.size() && out[lead] == ' ') ++lead;
  out.erase(0, lead);
  if (out.empty() || out == "time") out = "column" + out;
  return out;
}

void tidyTable(LogTable& table, const ReadOptions& options, ReadReport& report) {
  TableTidier(table, options, report).run();
}

LogTable mergeTables(std::vector<LogTable> tables, MergeNames names, const ReadOptions& options,
                     ReadReport& report) {
  if (tables.empty()) return {};
  if (tables.size() == 1) return std::move(tables.front());
  for (const auto& t : tables)
    if (t.epoch != tables.front().epoch)
      throw InputError("time",
                       "'" + t.file + "' has " + (t.epoch ? "absolute (date and time)" : "relative (seconds)") +
                           " time stamps but '" + tables.front().file + "' has " +
                           (tables.front().epoch ? "absolute" : "relative") + " ones; they cannot be put on one time base",
                       "give every file the same kind of time column (date and time, or seconds since the same start)",
                       {t.file, 0, 0});
  LogTable out;
  out.epoch = tables.front().epoch;
  out.file = tables.front().file;
  out.tag = tables.front().tag;
  std::size_t total = 0;
  for (const auto& t : tables) total += t.time.size();
  out.time.reserve(total);
  for (const auto& t : tables) out.time.insert(out.time.end(), t.time.begin(), t.time.end());
  std::sort(out.time.begin(), out.time.end());
  out.time.erase(std::unique(out.time.begin(), out.time.end()), out.time.end());
  const std::size_t n = out.time.size();
  report.rows_merged += static_cast<long long>(total - n);
  out.row_where.assign(n, 0);

  std::unordered_set<std::string> metaKeys;
  for (auto& t : tables)
    for (auto& m : t.metadata)
      if (m.key.empty() || metaKeys.insert(m.key).second) out.metadata.push_back(std::move(m));

  std::unordered_map<std::string, std::size_t> byName;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    LogTable& t = tables[k];
    std::vector<std::size_t> at(t.time.size());
    for (std::size_t i = 0, j = 0; i < t.time.size(); ++i) {
      while (out.time[j] < t.time[i]) ++j;
      at[i] = j;
      if (i < t.row_where.size() && out.row_where[j] == 0) out.row_where[j] = t.row_where[i];
    }
    for (auto& c : t.columns) {
      auto hit = byName.find(c.name);
      bool combine = hit != byName.end() && names == MergeNames::kCombine &&
                     out.columns[hit->second].unit == c.unit;
      if (hit != byName.end() && !combine) {
        std::string renamed = c.name + "_" + (t.tag.empty() ? std::to_string(k + 1) : t.tag);
        for (int s = 2; byName.count(renamed); ++s) renamed = c.name + "_" + std::to_string(s);
        ReadProblem p;
        p.kind = ReadProblemKind::kDuplicateColumn;
        p.where = c.where;
        p.column = c.name;
        p.problem = "'" + c.name + "' also comes from '" + out.columns[hit->second].where.file +
                    "'; this one is named '" + renamed + "'";
        p.fix = "map one of them to another channel in the column mapping if they are not the same sensor";
        report.add(std::move(p), options.max_problems_per_kind);
        c.name = renamed;
        hit = byName.end();
      }
      if (hit == byName.end()) {
        TableColumn d = c;
        d.values.clear();
        if (!c.values.empty()) {
          d.values.assign(n, kNaN);
          for (std::size_t i = 0; i < c.values.size(); ++i) d.values[at[i]] = c.values[i];
        }
        byName.emplace(d.name, out.columns.size());
        out.columns.push_back(std::move(d));
        continue;
      }
      TableColumn& d = out.columns[hit->second];
      if (c.values.empty()) continue;
      if (d.values.empty()) d.values.assign(n, kNaN);
      long long conflicts = 0;
      for (std::size_t i = 0; i < c.values.size(); ++i) {
        const double v = c.values[i];
        if (std::isnan(v)) continue;
        double& dst = d.values[at[i]];
        if (std::isnan(dst)) dst = v;
        else if (dst != v) ++conflicts;
      }
      if (conflicts) {
        ReadProblem p;
        p.kind = ReadProblemKind::kConflictingDuplicate;
        p.where = c.where;
        p.column = c.name;
        p.problem = std::to_string(conflicts) + " values differ between two sources at the same time; the first was kept";
        p.fix = "check the clocks of the two sources";
        report.add(std::move(p), options.max_problems_per_kind);
      }
    }
  }
  return out;
}

MissionLog finishTable(LogTable table, ReadReport& report, bool dropEmpty) {
  if (table.time.empty()) {
    std::string why = "no usable data rows";
    if (report.data_lines > 0)
      why += " (" + std::to_string(report.data_lines) + " rows, all skipped; first: " +
             (report.problems.empty() ? std::string("?") : report.problems.front().text()) + ")";
    throw InputError("rows", why, "the file needs at least one row with a valid time", {table.file, 0, 0});
  }
  MissionLog log;
  log.metadata = std::move(table.metadata);
  for (auto& m : log.metadata) {  // file text: may be Latin-1; must fit in `# key: value`
    m.key = toValidUtf8(m.key);
    m.value = toValidUtf8(m.value);
    for (std::string* t : {&m.key, &m.value})
      for (char& k : *t)
        if (k == '\r' || k == '\n' || k == '\0') k = ' ';
    if (m.key.find(':') != std::string::npos)
      for (char& k : m.key)
        if (k == ':') k = '_';
  }
  if (table.epoch && !table.time.empty()) {
    // Rounded down to the millisecond, but a time that is a whole millisecond
    // in decimal (1466704271.771) must not lose one to binary rounding.
    double ms = table.time.front() * 1000.0;
    if (std::fabs(ms - std::round(ms)) < 1e-3) ms = std::round(ms);
    const double start = std::floor(ms) / 1000.0;
    log.setMetadata("start", formatIso8601(start, 3));
    for (double& t : table.time) t -= start;
    // Subtracting the start can round two neighbouring instants onto one
    // value; such rows are merged like repeated time stamps.
    std::vector<char> keep(table.time.size(), 1);
    bool collapsed = false;
    for (std::size_t i = 1, prev = 0; i < table.time.size(); ++i) {
      if (table.time[i] > table.time[prev]) {
        prev = i;
        continue;
      }
      keep[i] = 0;
      collapsed = true;
      ++report.rows_merged;
      for (auto& c : table.columns)
        if (!c.values.empty() && std::isnan(c.values[prev])) c.values[prev] = c.values[i];
    }
    if (collapsed) {
      std::size_t w = 0;
      for (std::size_t i = 0; i < keep.size(); ++i) {
        if (!keep[i]) continue;
        table.time[w] = table.time[i];
        for (auto& c : table.columns)
          if (!c.values.empty()) c.values[w] = c.values[i];
        ++w;
      }
      table.time.resize(w);
      for (auto& c : table.columns)
        if (!c.values.empty()) c.values.resize(w);
      ReadProblem p;
      p.kind = ReadProblemKind::kDuplicateTime;
      p.where = {table.file, 0, 0};
      p.column = "time";
      p.problem = "time stamps closer than the clock's resolution after the start were merged";
      p.fix = "check the time stamps";
      report.add(std::move(p), 20);
    }
  }
  log.time = std::move(table.time);
  const std::size_t n = log.time.size();
  std::unordered_set<std::string> used{"time"};
  for (auto& c : table.columns) {
    std::size_t valid = 0;
    for (double v : c.values) valid += !std::isnan(v);
    if (dropEmpty && valid == 0) continue;
    LogChannel ch;
    ch.name = toValidUtf8(c.name);
    c.name = ch.name;
    for (int s = 2; used.count(ch.name); ++s) ch.name = c.name + "_" + std::to_string(s);
    used.insert(ch.name);
    ch.unit = toValidUtf8(c.unit);
    ch.source_unit = toValidUtf8(c.source_unit.empty() ? c.unit : c.source_unit);
    for (std::string* u : {&ch.unit, &ch.source_unit})  // must fit in a `name [unit]` header
      for (char& k : *u)
        if (k == ',' || k == '[' || k == ']' || k == '"' || static_cast<unsigned char>(k) < 0x20) k = '_';
    ch.values = std::move(c.values);
    ch.values.resize(n, kNaN);
    log.channels.push_back(std::move(ch));
  }
  report.rows_kept = static_cast<long long>(n);
  return log;
}

}  // namespace auv
