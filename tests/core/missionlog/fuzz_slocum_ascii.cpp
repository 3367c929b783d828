// libFuzzer target for the Slocum ASCII reader. If the first byte is odd, a
// valid dbd2asc header (tags and label lines for a merged engineering and
// science file) is put in front of the input so that the fuzzer spends its
// time on rows; otherwise the input is the whole file. The second bit picks a
// small read block. Checks fuzz_checks.h on every log.
#include <cstdint>
#include <string>

#include "fuzz_checks.h"
#include "missionlog/slocum_ascii_reader.h"

namespace {
constexpr const char* kHeader =
    "dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\n"
    "encoding_ver: 2\n"
    "num_ascii_tags: 14\n"
    "all_sensors: 0\n"
    "filename: fuzz-2023-318-0-5\n"
    "the8x3_filename: 00410005\n"
    "filename_extension: dbd\n"
    "filename_label: fuzz-2023-318-0-5-dbd(00410005)\n"
    "mission_name: YO10.MI\n"
    "fileopen_time: Tue_Nov_14_22:13:20_2023\n"
    "sensors_per_cycle: 8\n"
    "num_label_lines: 3\n"
    "num_segments: 1\n"
    "segment_filename_0: fuzz-2023-318-0-5\n"
    "m_present_time m_depth m_pitch m_battpos m_gps_lat sci_m_present_time sci_water_pressure m_de_oil_vol \n"
    "timestamp m rad in lat timestamp bar cc \n"
    "8 4 4 4 8 8 4 4 \n";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string text;
  if (data[0] & 1) text = kHeader;
  text.append(reinterpret_cast<const char*>(data) + 1, size - 1);
  auv::ReadOptions options;
  options.block_bytes = (data[0] & 2) ? 128 : 4096;
  options.max_problems_per_kind = 3;
  auv::ReadReport report;
  try {
    const auv::MissionLog log = auv::parseSlocumAscii(text, "fuzz.dba", options, report);
    auv::fuzz::checkLog(log, report, options.max_abs_value);
    auv::fuzz::roundTrip(log);
  } catch (const auv::InputError& e) {
    check(e.what()[0] != '\0');
  }
  return 0;
}
