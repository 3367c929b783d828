// libFuzzer target for the delimited-text reader. The first byte picks the
// read block size and the column mapping (none, a ';' / decimal-comma one,
// a whitespace one with a date column); the rest is the file. Besides "no
// crash, no sanitizer report" it checks fuzz_checks.h on every log, and that
// the mapping suggested for the same text survives JSON and back.
#include <cstdint>
#include <string_view>

#include "fuzz_checks.h"
#include "missionlog/delimited_text_reader.h"

namespace {

const auv::ColumnMapping& mapping(int which) {
  static const auv::ColumnMapping none;
  static const auv::ColumnMapping semicolon = auv::ColumnMapping::fromJson(R"({
    "column_mapping_version": 1, "delimiter": ";", "decimal": ",",
    "time": {"column": "Tid", "format": "dd.mm.yyyy hh:mm:ss", "utc_offset_hours": 2},
    "columns": [{"header": "Djup", "channel": "depth", "unit": "m"},
                {"header": "Status", "ignore": true},
                {"header": "Rull", "channel": "roll", "unit": "rad", "scale": -1}]})", "fuzz-mapping.json");
  static const auv::ColumnMapping blanks = auv::ColumnMapping::fromJson(R"({
    "column_mapping_version": 1, "delimiter": "whitespace",
    "time": {"column": "Time", "format": "hh:mm:ss", "date_column": "Date"}})", "fuzz-mapping2.json");
  return which == 1 ? semicolon : which == 2 ? blanks : none;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  static constexpr std::size_t kBlocks[] = {64, 97, 256, 4096};
  auv::ReadOptions options;
  options.block_bytes = kBlocks[data[0] % 4];
  options.max_problems_per_kind = 3;
  auv::ReadReport report;
  try {
    const auv::MissionLog log = auv::parseDelimitedText(text, "fuzz.txt", mapping((data[0] >> 2) % 3), options, report);
    auv::fuzz::checkLog(log, report, options.max_abs_value);
    auv::fuzz::roundTrip(log);
  } catch (const auv::InputError& e) {
    check(e.what()[0] != '\0');
  }
  try {
    const auv::ColumnMapping m = auv::suggestColumnMapping(text, "fuzz.txt");
    const auv::ColumnMapping back = auv::ColumnMapping::fromJson(m.toJson(), "suggested.json");
    check(back.toJson() == m.toJson());
  } catch (const auv::InputError& e) {
    check(e.what()[0] != '\0');
  }
  return 0;
}
