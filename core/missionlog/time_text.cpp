#include "missionlog/time_text.h"

#include <charconv>
#include <cmath>
#include <string>

#include "missionlog/detail/ascii_text.h"

namespace auv {
namespace {

using detail::isDigit;

// 1..maxDigits digits at s[i]; advances i.
bool number(std::string_view s, std::size_t& i, int minDigits, int maxDigits, long long& out) {
  const std::size_t start = i;
  long long v = 0;
  while (i < s.size() && isDigit(s[i]) && static_cast<int>(i - start) < maxDigits) v = v * 10 + (s[i++] - '0');
  const auto n = static_cast<int>(i - start);
  if (n < minDigits) return false;
  out = v;
  return true;
}

// hh:mm[:ss[.fff]] starting at s[i]; the whole rest must be consumed when `toEnd`.
bool clock(std::string_view s, std::size_t& i, double& seconds) {
  long long h = 0, m = 0;
  if (!number(s, i, 1, 2, h) || i >= s.size() || s[i] != ':') return false;
  ++i;
  if (!number(s, i, 2, 2, m)) return false;
  double sec = 0.0;
  if (i < s.size() && s[i] == ':') {
    ++i;
    const std::size_t start = i;
    while (i < s.size() && isDigit(s[i])) ++i;
    if (i - start != 2) return false;
    if (i < s.size() && (s[i] == '.' || s[i] == ',')) {
      ++i;
      const std::size_t f = i;
      while (i < s.size() && isDigit(s[i])) ++i;
      if (i == f) return false;
    }
    std::string buf(s.substr(start, i - start));
    if (buf.size() > 2) buf[2] = '.';
    const auto r = std::from_chars(buf.data(), buf.data() + buf.size(), sec);
    if (r.ec != std::errc{} || r.ptr != buf.data() + buf.size()) return false;
  }
  if (h > 24 || m > 59 || sec >= 61.0 || (h == 24 && (m > 0 || sec > 0.0))) return false;
  seconds = static_cast<double>(h * 3600 + m * 60) + sec;
  return true;
}

using detail::trim;

bool dayMonthYear(std::string_view s, std::size_t& i, long long& days) {
  long long d = 0, m = 0, y = 0;
  if (!number(s, i, 1, 2, d) || i >= s.size() || s[i] != '.') return false;
  ++i;
  if (!number(s, i, 1, 2, m) || i >= s.size() || s[i] != '.') return false;
  ++i;
  if (!number(s, i, 4, 4, y)) return false;
  const auto c = civilDays(y, static_cast<int>(m), static_cast<int>(d));
  if (!c) return false;
  days = *c;
  return true;
}

bool yearMonthDay(std::string_view s, std::size_t& i, long long& days, int minDigits) {
  long long d = 0, m = 0, y = 0;
  if (!number(s, i, 4, 4, y) || i >= s.size() || s[i] != '-') return false;
  ++i;
  if (!number(s, i, minDigits, 2, m) || i >= s.size() || s[i] != '-') return false;
  ++i;
  if (!number(s, i, minDigits, 2, d)) return false;
  const auto c = civilDays(y, static_cast<int>(m), static_cast<int>(d));
  if (!c) return false;
  days = *c;
  return true;
}

}  // namespace

std::optional<long long> civilDays(long long y, int m, int d) {
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (m < 1 || m > 12 || d < 1 || y < 1 || y > 9999) return std::nullopt;
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  if (d > kDays[m - 1] + (m == 2 && leap)) return std::nullopt;
  // H. Hinnant's days_from_civil.
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const long long yoe = y - era * 400;
  const long long doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const long long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

std::optional<double> parseDayMonthYear(std::string_view text) {
  const std::string_view s = trim(text);
  std::size_t i = 0;
  long long days = 0;
  if (!dayMonthYear(s, i, days)) return std::nullopt;
  double sec = 0.0;
  if (i < s.size()) {
    if (s[i] != ' ' && s[i] != 'T' && s[i] != '_') return std::nullopt;
    while (i < s.size() && (s[i] == ' ' || s[i] == 'T' || s[i] == '_')) ++i;
    if (!clock(s, i, sec) || i != s.size()) return std::nullopt;
  }
  return static_cast<double>(days) * 86400.0 + sec;
}

std::optional<double> parseDateOnly(std::string_view text) {
  const std::string_view s = trim(text);
  std::size_t i = 0;
  long long days = 0;
  if (!(dayMonthYear(s, i, days) || (i = 0, yearMonthDay(s, i, days, 2))) || i != s.size()) return std::nullopt;
  return static_cast<double>(days) * 86400.0;
}

std::optional<double> parseTimeOfDay(std::string_view text) {
  const std::string_view s = trim(text);
  std::size_t i = 0;
  double sec = 0.0;
  if (!clock(s, i, sec) || i != s.size()) return std::nullopt;
  return sec;
}

std::optional<CfTimeUnits> parseCfTimeUnits(std::string_view units) {
  std::string_view s = trim(units);
  const auto since = s.find(" since ");
  if (since == std::string_view::npos) return std::nullopt;
  std::string word(trim(s.substr(0, since)));
  for (char& c : word)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  double scale = 0.0;
  if (word == "seconds" || word == "second" || word == "secs" || word == "sec" || word == "s") scale = 1.0;
  else if (word == "milliseconds" || word == "millisecond" || word == "msec" || word == "ms") scale = 1e-3;
  else if (word == "minutes" || word == "minute" || word == "mins" || word == "min") scale = 60.0;
  else if (word == "hours" || word == "hour" || word == "hrs" || word == "hr" || word == "h") scale = 3600.0;
  else if (word == "days" || word == "day" || word == "d") scale = 86400.0;
  else return std::nullopt;
  const std::string_view ref = trim(s.substr(since + 7));
  std::size_t i = 0;
  long long days = 0;
  if (!yearMonthDay(ref, i, days, 1)) return std::nullopt;
  double sec = 0.0;
  if (i < ref.size() && (ref[i] == 'T' || ref[i] == ' ')) {
    std::size_t j = i;
    while (j < ref.size() && (ref[j] == 'T' || ref[j] == ' ')) ++j;
    if (j < ref.size() && isDigit(ref[j])) {
      i = j;
      if (!clock(ref, i, sec)) return std::nullopt;
    }
  }
  // Zone: Z, UTC, GMT, +hh[:mm] / -hh[:mm] / +hhmm.
  std::string_view zone = trim(ref.substr(i));
  double zoneSeconds = 0.0;
  if (!zone.empty() && zone != "Z" && zone != "z" && zone != "UTC" && zone != "GMT" && zone != "utc") {
    if (zone.front() != '+' && zone.front() != '-') return std::nullopt;
    const double sign = zone.front() == '-' ? -1.0 : 1.0;
    std::size_t k = 1;
    long long hh = 0, mm = 0;
    if (!number(zone, k, 1, 2, hh)) return std::nullopt;
    if (k < zone.size() && zone[k] == ':') ++k;
    if (k < zone.size() && !number(zone, k, 2, 2, mm)) return std::nullopt;
    if (k != zone.size() || hh > 14 || mm > 59) return std::nullopt;
    zoneSeconds = sign * static_cast<double>(hh * 3600 + mm * 60);
  }
  return CfTimeUnits{scale, static_cast<double>(days) * 86400.0 + sec - zoneSeconds};
}

}  // namespace auv
