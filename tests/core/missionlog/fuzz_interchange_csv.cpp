// libFuzzer target for the interchange CSV reader. Besides "no crash, no
// sanitizer report" it checks the reader's promises on every input: either an
// InputError, or a log whose time is finite and strictly increasing, whose
// channels all have one value per row, with no value beyond the fill-value
// limit, whose report accounts for every data line, and which survives
// write -> read unchanged. The first byte also picks a small block size so
// that lines straddling block boundaries and overlong lines get exercised.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string_view>

#include "common/input_error.h"
#include "missionlog/decimal_parse.h"
#include "missionlog/interchange_csv.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

bool sameBits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void checkLog(const auv::MissionLog& log, const auv::ReadReport& r, double maxAbs) {
  check(r.rows_kept == static_cast<long long>(log.rowCount()));
  check(r.data_lines == r.rows_kept + r.rows_skipped + r.rows_merged);
  check(log.rowCount() > 0);
  for (std::size_t i = 0; i < log.rowCount(); ++i) {
    check(std::isfinite(log.time[i]));
    if (i) check(log.time[i] > log.time[i - 1]);
  }
  for (const auto& c : log.channels) {
    check(c.values.size() == log.rowCount());
    for (double v : c.values) check(std::isnan(v) || std::fabs(v) <= maxAbs * 1e6);
  }
}

void roundTrip(const auv::MissionLog& log) {
  std::ostringstream out;
  try {
    auv::writeInterchangeCsv(log, out);
  } catch (const auv::InputError&) {
    return;  // e.g. a channel name the writer cannot express; refusing is fine
  }
  auv::ReadReport r;
  const auv::MissionLog back = auv::parseInterchangeCsv(out.str(), "roundtrip", {}, r);
  check(back.rowCount() == log.rowCount());
  check(back.channels.size() == log.channels.size());
  check(back.metadata.size() == log.metadata.size());
  for (std::size_t i = 0; i < log.rowCount(); ++i) check(sameBits(back.time[i], log.time[i]));
  for (std::size_t c = 0; c < log.channels.size(); ++c) {
    check(back.channels[c].name == log.channels[c].name);
    for (std::size_t i = 0; i < log.rowCount(); ++i)
      check(sameBits(back.channels[c].values[i], log.channels[c].values[i]));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);

  // The fast number parser must agree with std::from_chars on any prefix.
  {
    const std::string_view head = text.substr(0, 40);
    double a = 0.0, b = 0.0;
    const char* pa = auv::parseDecimal(head.data(), head.data() + head.size(), a);
    const auto rb = std::from_chars(head.data(), head.data() + head.size(), b);
    if (rb.ec == std::errc{}) check(pa == rb.ptr && sameBits(a, b));
    else check(pa == nullptr);
  }

  auv::ReadOptions options;
  if (size > 0) {
    static constexpr std::size_t kBlocks[] = {64, 97, 256, 4096};
    options.block_bytes = kBlocks[data[0] % 4];
  }
  options.max_problems_per_kind = 3;
  auv::ReadReport report;
  try {
    const auv::MissionLog log = auv::parseInterchangeCsv(text, "fuzz.csv", options, report);
    checkLog(log, report, options.max_abs_value);
    roundTrip(log);
  } catch (const auv::InputError& e) {
    check(e.what()[0] != '\0');
  }
  return 0;
}
