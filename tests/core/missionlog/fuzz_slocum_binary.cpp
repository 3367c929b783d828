// libFuzzer target for the Slocum binary reader. The first byte steers: bit 0
// puts the rest into LZ4 block framing (so that mutations reach the decoder
// behind it), bit 1 puts a valid header, sensor list and known-bytes cycle in
// front (so that the fuzzer spends its time on data cycles), bit 2 makes
// that prefix big-endian. No cache folder exists and the per-user cache is
// off: factored files must be refused, never looked up on disk. Checks
// fuzz_checks.h on every log.
#include <cstdint>
#include <string>

#include "fuzz_checks.h"
#include "missionlog/detail/slocum_lz4.h"
#include "missionlog/slocum_binary_reader.h"
#include "slocum_test_writer.h"

namespace {

std::string prefix(bool big) {
  auv::test::SlocumWriterFile f;
  f.big_endian = big;
  f.end_tag = false;
  f.sensors = {{"m_present_time", "timestamp", 8}, {"m_depth", "m", 4},  {"m_pitch", "rad", 4},
               {"m_battpos", "in", 4},             {"m_gps_lat", "lat", 8}, {"u_test_int8", "nodim", 1},
               {"u_test_int16", "nodim", 2},       {"sci_water_pressure", "bar", 4}, {"m_de_oil_vol", "cc", 4}};
  return auv::test::writeSlocumBinary(f);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const std::string little = prefix(false), big = prefix(true);
  std::string bytes;
  if (data[0] & 2) bytes = (data[0] & 4) ? big : little;
  bytes.append(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] & 1) bytes = auv::detail::slocumLz4Compress(bytes);
  auv::ReadOptions options;
  options.max_problems_per_kind = 3;
  options.slocum_user_cache = false;
  auv::ReadReport report;
  try {
    const auv::MissionLog log = auv::parseSlocumBinary(bytes, "/nonexistent-fuzz-dir/fuzz.dbd", options, report);
    auv::fuzz::checkLog(log, report, options.max_abs_value);
    auv::fuzz::roundTrip(log);
  } catch (const auv::InputError& e) {
    check(e.what()[0] != '\0');
  }
  return 0;
}
