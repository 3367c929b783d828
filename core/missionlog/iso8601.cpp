#include "missionlog/iso8601.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace auv {
namespace {

// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's algorithm).
std::int64_t daysFromCivil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

void civilFromDays(std::int64_t z, std::int64_t& y, unsigned& m, unsigned& d) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  y = static_cast<std::int64_t>(yoe) + era * 400;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = doy - (153 * mp + 2) / 5 + 1;
  m = mp < 10 ? mp + 3 : mp - 9;
  y += m <= 2;
}

bool isLeap(std::int64_t y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

unsigned daysInMonth(std::int64_t y, unsigned m) {
  static constexpr unsigned kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && isLeap(y) ? 29 : kDays[m - 1];
}

// Exactly n decimal digits at p (p + n <= end checked by the caller).
bool digits(const char* p, const char* end, int n, unsigned& out) {
  if (end - p < n) return false;
  unsigned v = 0;
  for (int i = 0; i < n; ++i) {
    const char c = p[i];
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<unsigned>(c - '0');
  }
  out = v;
  return true;
}

}  // namespace

const char* parseIso8601Prefix(const char* p, const char* end, double& epochSeconds,
                               bool& hadZone) {
  unsigned year = 0, month = 0, day = 0;
  if (!digits(p, end, 4, year) || end - p < 10 || p[4] != '-' || !digits(p + 5, end, 2, month) ||
      p[7] != '-' || !digits(p + 8, end, 2, day))
    return nullptr;
  if (month < 1 || month > 12 || day < 1 || day > daysInMonth(year, month)) return nullptr;
  p += 10;
  unsigned hour = 0, minute = 0, sec = 0;
  double fraction = 0.0;
  if (p < end && (*p == 'T' || *p == ' ') && end - p >= 6 && p[1] >= '0' && p[1] <= '9') {
    if (!digits(p + 1, end, 2, hour) || p[3] != ':' || !digits(p + 4, end, 2, minute)) return nullptr;
    p += 6;
    if (p < end && *p == ':') {
      if (!digits(p + 1, end, 2, sec)) return nullptr;
      p += 3;
      if (p < end && (*p == '.' || *p == ',')) {
        ++p;
        double scale = 0.1;
        const char* first = p;
        while (p < end && *p >= '0' && *p <= '9') {
          fraction += (*p - '0') * scale;
          scale *= 0.1;
          ++p;
        }
        if (p == first) return nullptr;
      }
    }
    // 60 is allowed for a leap second; it counts into the next minute.
    if (hour > 23 || minute > 59 || sec > 60) return nullptr;
  }
  double zoneOffset = 0.0;
  hadZone = false;
  if (p < end && *p == 'Z') {
    hadZone = true;
    ++p;
  } else if (p < end && (*p == '+' || *p == '-') && end - p >= 3) {
    const double sign = *p == '+' ? 1.0 : -1.0;
    unsigned zh = 0, zm = 0;
    if (!digits(p + 1, end, 2, zh)) return nullptr;
    p += 3;
    if (p < end && *p == ':') {
      if (!digits(p + 1, end, 2, zm)) return nullptr;
      p += 3;
    } else if (end - p >= 2 && p[0] >= '0' && p[0] <= '9') {
      if (!digits(p, end, 2, zm)) return nullptr;
      p += 2;
    }
    if (zh > 23 || zm > 59) return nullptr;
    hadZone = true;
    zoneOffset = sign * (zh * 3600.0 + zm * 60.0);
  }
  const std::int64_t days = daysFromCivil(year, month, day);
  const double whole = static_cast<double>(days * 86400 + hour * 3600 + minute * 60 + sec);
  epochSeconds = whole + fraction - zoneOffset;
  return p;
}

std::optional<double> parseIso8601(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  double t = 0.0;
  bool zone = false;
  const char* end = text.data() + text.size();
  const char* p = parseIso8601Prefix(text.data(), end, t, zone);
  if (!p || p != end) return std::nullopt;
  return t;
}

std::string formatIso8601(double epochSeconds, int fractionDigits) {
  if (!std::isfinite(epochSeconds)) return "invalid";
  if (fractionDigits < 0) fractionDigits = 0;
  if (fractionDigits > 9) fractionDigits = 9;
  const double unit = std::pow(10.0, fractionDigits);
  // Round once to the requested resolution so 59.9996 s never prints as "60.000".
  const double ticks = std::round(epochSeconds * unit);
  if (std::fabs(ticks) > 9e18) return "out-of-range";
  const auto ticksPerDay = static_cast<std::int64_t>(86400 * unit);
  auto total = static_cast<std::int64_t>(ticks);
  std::int64_t days = total / ticksPerDay;
  std::int64_t rem = total % ticksPerDay;
  if (rem < 0) {
    rem += ticksPerDay;
    --days;
  }
  const auto perSecond = static_cast<std::int64_t>(unit);
  const std::int64_t secOfDay = rem / perSecond;
  const std::int64_t frac = rem % perSecond;
  std::int64_t y = 0;
  unsigned m = 0, d = 0;
  civilFromDays(days, y, m, d);
  char buf[64];
  int n = std::snprintf(buf, sizeof buf, "%04lld-%02u-%02uT%02lld:%02lld:%02lld",
                        static_cast<long long>(y), m, d, static_cast<long long>(secOfDay / 3600),
                        static_cast<long long>(secOfDay / 60 % 60),
                        static_cast<long long>(secOfDay % 60));
  std::string s(buf, static_cast<std::size_t>(n));
  if (fractionDigits > 0) {
    n = std::snprintf(buf, sizeof buf, ".%0*lld", fractionDigits, static_cast<long long>(frac));
    s.append(buf, static_cast<std::size_t>(n));
  }
  return s + "Z";
}

}  // namespace auv
