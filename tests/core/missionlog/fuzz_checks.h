#pragma once
// The promises every reader keeps on any input, checked by the libFuzzer
// targets of the vendor readers: a log has finite, strictly increasing time,
// one value per row in every channel, no value beyond the fill-value limit
// (1e6 x margin for unit conversions), a report that accounts for every
// data line, and it survives write -> read through the interchange CSV.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "common/input_error.h"
#include "missionlog/interchange_csv.h"

namespace auv::fuzz {

inline void checkAt(bool ok, const char* what, int line) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_checks.h:%d: broken promise: %s\n", line, what);
  std::abort();
}
#define check(cond) ::auv::fuzz::checkAt((cond), #cond, __LINE__)

inline bool sameBits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

inline void checkLog(const MissionLog& log, const ReadReport& r, double maxAbs) {
  check(r.rows_kept == static_cast<long long>(log.rowCount()));
  check(r.data_lines == r.rows_kept + r.rows_skipped + r.rows_merged);
  check(log.rowCount() > 0);
  for (std::size_t i = 0; i < log.rowCount(); ++i) {
    check(std::isfinite(log.time[i]));
    if (i) check(log.time[i] > log.time[i - 1]);
  }
  for (const auto& c : log.channels) {
    check(!c.name.empty() && c.name != "time");
    check(c.values.size() == log.rowCount());
    for (double v : c.values) check(std::isnan(v) || std::fabs(v) <= maxAbs * 1e6);
  }
  for (std::size_t a = 0; a < log.channels.size(); ++a)
    for (std::size_t b = a + 1; b < log.channels.size(); ++b) check(log.channels[a].name != log.channels[b].name);
}

inline void roundTrip(const MissionLog& log) {
  std::ostringstream out;
  try {
    writeInterchangeCsv(log, out);
  } catch (const InputError&) {
    return;  // e.g. a channel name the writer cannot express; refusing is fine
  }
  ReadReport r;
  const MissionLog back = parseInterchangeCsv(out.str(), "roundtrip", {}, r);
  check(back.rowCount() == log.rowCount());
  check(back.channels.size() == log.channels.size());
  for (std::size_t i = 0; i < log.rowCount(); ++i) check(sameBits(back.time[i], log.time[i]));
  for (std::size_t c = 0; c < log.channels.size(); ++c)
    for (std::size_t i = 0; i < log.rowCount(); ++i) check(sameBits(back.channels[c].values[i], log.channels[c].values[i]));
}

}  // namespace auv::fuzz
