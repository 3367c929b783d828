#include "missionlog/text_cells.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "missionlog/decimal_overflow.h"
#include "missionlog/decimal_parse.h"
#include "missionlog/detail/ascii_text.h"

namespace auv {
namespace {

using detail::iequals;

}  // namespace

bool isMissingSpelling(std::string_view c) {
  if (c.empty()) return true;
  switch (c.front()) {  // every spelling below starts with one of these
    case 'n': case 'N': case '-': case '+': case '*': case '#': break;
    default: return false;
  }
  if (c.size() <= 3 && c.find_first_not_of('-') == std::string_view::npos) return true;
  if (c.find_first_not_of('*') == std::string_view::npos) return true;
  for (std::string_view s : {"nan", "-nan", "+nan", "na", "n/a", "null", "none", "nil", "#n/a"})
    if (iequals(c, s)) return true;
  return false;
}

CellValue parseNumberCell(std::string_view cell, bool decimalComma, double& v) {
  char buf[72];
  // Fast paths: a plain number filling the whole cell, or one with a decimal comma.
  if (!cell.empty()) {
    const char* end = cell.data() + cell.size();
    const char* stop = parseDecimal(cell.data(), end, v);
    if (stop == end) return std::isnan(v) ? CellValue::kEmpty : CellValue::kNumber;
    if (decimalComma && stop && *stop == ',' && cell.size() < sizeof buf) {
      const std::size_t at = static_cast<std::size_t>(stop - cell.data());
      cell.copy(buf, cell.size());
      buf[at] = '.';
      if (parseDecimal(buf, buf + cell.size(), v) == buf + cell.size() && cell.find('.') == std::string_view::npos)
        return std::isnan(v) ? CellValue::kEmpty : CellValue::kNumber;
    }
  }
  while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
  while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t')) cell.remove_suffix(1);
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') {
    cell = cell.substr(1, cell.size() - 2);
    while (!cell.empty() && cell.front() == ' ') cell.remove_prefix(1);
    while (!cell.empty() && cell.back() == ' ') cell.remove_suffix(1);
  }
  if (isMissingSpelling(cell)) return CellValue::kEmpty;
  if (cell.front() == '+') {
    cell.remove_prefix(1);
    if (cell.empty() || cell.front() == '-' || cell.front() == '+') return CellValue::kBad;
  }
  if (decimalComma) {
    const auto comma = cell.find(',');
    if (comma != std::string_view::npos) {
      if (cell.size() >= sizeof buf || cell.find(',', comma + 1) != std::string_view::npos ||
          cell.find('.') != std::string_view::npos)
        return CellValue::kBad;
      cell.copy(buf, cell.size());
      buf[comma] = '.';
      cell = std::string_view(buf, cell.size());
    }
  }
  const char* end = cell.data() + cell.size();
  const auto r = std::from_chars(cell.data(), end, v);
  if (r.ptr != end || r.ec == std::errc::invalid_argument) return CellValue::kBad;
  if (r.ec == std::errc::result_out_of_range) {
    const bool negative = cell.front() == '-';
    v = decimalOverflows(cell) ? (negative ? -1.0 : 1.0) * std::numeric_limits<double>::infinity() : (negative ? -0.0 : 0.0);
    return CellValue::kNumber;
  }
  return std::isnan(v) ? CellValue::kEmpty : CellValue::kNumber;
}

}  // namespace auv
