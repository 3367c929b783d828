#include "history/timestamp.h"

#include <cstdio>

#include "common/input_error.h"

namespace auv {
using namespace std::chrono;

TimePoint nowUtc() { return floor<seconds>(system_clock::now()); }

std::string toIsoUtc(TimePoint t) {
  const auto day = floor<days>(t);
  const year_month_day ymd{day};
  const hh_mm_ss hms{t - day};
  char buf[32];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02d:%02d:%02dZ", int(ymd.year()),
                unsigned(ymd.month()), unsigned(ymd.day()), int(hms.hours().count()),
                int(hms.minutes().count()), int(hms.seconds().count()));
  return buf;
}

TimePoint makeUtc(int y, unsigned mo, unsigned d, int h, int mi, int s) {
  const year_month_day ymd{year{y}, month{mo}, day{d}};
  if (!ymd.ok() || h < 0 || h > 23 || mi < 0 || mi > 59 || s < 0 || s > 59)
    throw InputError("date", "no such date/time: " + std::to_string(y) + "-" +
                                 std::to_string(mo) + "-" + std::to_string(d) + " " +
                                 std::to_string(h) + ":" + std::to_string(mi) + ":" +
                                 std::to_string(s),
                     "give a real calendar date and a 24-hour time");
  return sys_days{ymd} + hours{h} + minutes{mi} + seconds{s};
}

TimePoint parseIsoUtc(const std::string& text, const std::string& field) {
  // Strict on purpose: we only ever read what we wrote, so anything else is damage.
  const char* fix = "expected UTC time as YYYY-MM-DDTHH:MM:SSZ";
  auto digits = [&](std::size_t pos, std::size_t n) {
    int v = 0;
    for (std::size_t i = pos; i < pos + n; ++i) {
      if (text[i] < '0' || text[i] > '9')
        throw InputError(field, "'" + text + "' is not an ISO-8601 UTC time", fix);
      v = v * 10 + (text[i] - '0');
    }
    return v;
  };
  if (text.size() != 20 || text[4] != '-' || text[7] != '-' || text[10] != 'T' ||
      text[13] != ':' || text[16] != ':' || text[19] != 'Z')
    throw InputError(field, "'" + text + "' is not an ISO-8601 UTC time", fix);
  return makeUtc(digits(0, 4), unsigned(digits(5, 2)), unsigned(digits(8, 2)), digits(11, 2),
                 digits(14, 2), digits(17, 2));
}

}  // namespace auv
