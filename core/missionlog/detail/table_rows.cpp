#include "missionlog/detail/table_rows.h"

#include "missionlog/iso8601.h"

namespace auv::detail {

InputLocation rowLocation(const LogTable& t, std::size_t i) {
  if (!t.record_dimension.empty()) return {t.file, 0, 0};
  return {t.file, i < t.row_where.size() ? static_cast<long>(t.row_where[i]) : 0, 0};
}

std::string rowPrefix(const LogTable& t, std::size_t i) {
  if (t.record_dimension.empty() || i >= t.row_where.size()) return {};
  return t.record_dimension + "[" + std::to_string(t.row_where[i]) + "]: ";
}

std::string rowName(const LogTable& t, std::size_t i) {
  if (i >= t.row_where.size()) return "?";
  if (!t.record_dimension.empty()) return t.record_dimension + "[" + std::to_string(t.row_where[i]) + "]";
  return "line " + std::to_string(t.row_where[i]);
}

std::string timeText(double t, bool epoch) {
  return epoch ? formatIso8601(t, 3) : numberText(t) + " s";
}

void keepRows(LogTable& t, const std::vector<char>& keep) {
  std::size_t w = 0;
  const std::size_t n = t.time.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!keep[i]) continue;
    if (w != i) {
      t.time[w] = t.time[i];
      if (i < t.row_where.size()) t.row_where[w] = t.row_where[i];
      for (auto& c : t.columns)
        if (!c.values.empty()) c.values[w] = c.values[i];
    }
    ++w;
  }
  t.time.resize(w);
  if (t.row_where.size() > w) t.row_where.resize(w);
  for (auto& c : t.columns)
    if (!c.values.empty()) c.values.resize(w);
}

}  // namespace auv::detail
