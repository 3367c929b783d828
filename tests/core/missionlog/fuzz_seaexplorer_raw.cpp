// libFuzzer target for the SeaExplorer raw reader. The first byte picks the
// shape: bit 0 puts a valid navigation header in front of the input (the
// fuzzer then spends its time on rows), bit 1 gzips the result with zlib (the
// table parser behind a good gzip), bit 2 picks a payload file name instead
// of a navigation one; with neither bit 0 nor 1 the input is the whole file
// (damaged and hostile gzip). Inflation is capped at 1 MiB. Checks
// fuzz_checks.h on every log.
#include <cstdint>
#include <string>

#include "fuzz_checks.h"
#include "gzip_test_bytes.h"
#include "missionlog/seaexplorer_raw_reader.h"

namespace {
constexpr const char* kHeader =
    "Timestamp;NavState;SecurityLevel;Heading;Declination;Pitch;Roll;Depth;Temperature;Pa;Lat;Lon;DesiredH;"
    "BallastCmd;BallastPos;LinCmd;LinPos;AngCmd;AngPos;Voltage;Altitude;\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string bytes;
  if (data[0] & 1) bytes = kHeader;
  bytes.append(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] & 2) bytes = auv::testing::gzipBytes(bytes);
  const std::string name = (data[0] & 4) ? "fuzz.7.pld1.raw.3.gz" : "fuzz.7.gli.sub.3.gz";
  auv::ReadOptions options;
  options.max_problems_per_kind = 3;
  options.block_bytes = 4096;
  auv::ReadReport report;
  try {
    const auv::MissionLog log = auv::parseSeaExplorerRaw(bytes, name, options, report, std::size_t{1} << 20);
    auv::fuzz::checkLog(log, report, options.max_abs_value);
    auv::fuzz::roundTrip(log);
  } catch (const auv::InputError& e) {
    check(e.what()[0] != '\0');
  }
  return 0;
}
