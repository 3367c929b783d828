// The registry picks every reader by content, and every real recording in
// shared/data/real still imports cleanly through it now that the generic
// text reader (which would also accept them) is registered.
#include <gtest/gtest.h>

#include <filesystem>

#include "missionlog/delimited_text_reader.h"
#include "missionlog/interchange_csv.h"
#include "missionlog/log_reader.h"
#include "missionlog/slocum_ascii_reader.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

fs::path fixture(const std::string& name) { return fs::path(AUV_TEST_DATA_DIR) / "missionlog" / name; }

std::string formatOf(const std::string& name) {
  static const LogReaderRegistry reg = LogReaderRegistry::withBuiltinReaders();
  const LogReader* r = reg.find(fixture(name));
  return r ? r->formatName() : "none";
}

TEST(ReaderRegistry, PicksEachReaderByContent) {
  const std::string csv = InterchangeCsvReader().formatName();
  const std::string text = DelimitedTextReader().formatName();
  const std::string slocum = SlocumAsciiReader().formatName();
  EXPECT_EQ(formatOf("good_minimal.csv"), csv);
  EXPECT_EQ(formatOf("hugin_depth_equivalent.csv"), csv);
  EXPECT_EQ(formatOf("hugin_depth.txt"), text);
  EXPECT_EQ(formatOf("hugin_misc.txt"), text);
  EXPECT_EQ(formatOf("hugin_nav.txt"), text);
  EXPECT_EQ(formatOf("hugin_velocity.txt"), text);
  EXPECT_EQ(formatOf("delimited_header_styles.csv"), text);
  EXPECT_EQ(formatOf("bad_no_time_column.csv"), text);  // `Time (s)` is no interchange header, but readable
  EXPECT_EQ(formatOf("slocum_merged.dba"), slocum);
  EXPECT_EQ(formatOf("slocum_shallow.asc"), slocum);
  EXPECT_EQ(formatOf("bad_random.bin"), "none");
  EXPECT_EQ(formatOf("bad_utf16.csv"), "none");
  EXPECT_EQ(formatOf("bad_delim_one_column.txt"), "none");
  EXPECT_EQ(formatOf("hugin_misc_no.txt"), "none");  // needs its column mapping
}

TEST(ReaderRegistry, EveryRealRecordingImportsCleanlyThroughTheRegistry) {
  const fs::path dir = fs::path(AUV_SHARED_DIR) / "data" / "real";
  if (!fs::exists(dir)) GTEST_SKIP() << "shared data folder " << dir << " not present; skipping";
  const auto reg = LogReaderRegistry::withBuiltinReaders();
  int n = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".csv") continue;
    // slocum-binary-samples/oracle/*.values.csv: per-sensor reference decodings, not logs.
    if (entry.path().parent_path().filename() == "oracle") continue;
    if (entry.path().filename().string().find("constants") != std::string::npos) {
      // A per-dive table (no time column): not a log, and no reader claims it.
      EXPECT_EQ(reg.find(entry.path()), nullptr) << entry.path();
      continue;
    }
    ++n;
    ReadReport r;
    const MissionLog log = reg.read(entry.path(), {}, r);
    EXPECT_GT(log.rowCount(), 1000u) << entry.path();
    EXPECT_EQ(r.format, "mission-log CSV v1") << entry.path();
    EXPECT_TRUE(r.clean()) << r.summary();
  }
  EXPECT_EQ(n, 4);
}

}  // namespace
}  // namespace auv
