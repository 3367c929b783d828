#include "missionlog/detail/delimited_column_plan.h"

#include <unordered_set>

#include "common/input_error.h"
#include "missionlog/channel_aliases.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"

namespace auv::detail {
namespace {

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

}  // namespace

Plan planColumns(const Layout& L, const ColumnMapping& m, const std::string& file, const ReadOptions& options,
                 ReadReport& report) {
  Plan p;
  p.table.file = file;
  p.target.assign(L.fields.size(), Plan::kIgnore);
  auto where = [&](std::size_t k) { return InputLocation{file, L.headerLine, L.fieldColumn[k]}; };
  auto note = [&](ReadProblemKind kind, std::size_t k, std::string column, std::string what, std::string fix) {
    reportProblem(report, options, kind, where(k), std::move(column), std::move(what), std::move(fix));
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

}  // namespace auv::detail
