// `--log` as a whole mission: a folder, or the flag repeated, in convert and
// analyze (the same core readMission serves model-check and simulate
// --replay). CI fixtures in tests/data/missionlog; the real raw folders in
// ../shared are compared with the CSV made from the same files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "missionlog/interchange_csv.h"

namespace auv {
namespace {
namespace fs = std::filesystem;
using testing::runCli;

fs::path data(const std::string& rel) { return fs::path(AUV_TEST_DATA_DIR) / "missionlog" / rel; }
fs::path real(const std::string& rel) { return fs::path(AUV_SHARED_DIR) / "data" / "real" / rel; }
std::string tmp(const std::string& name) { return ::testing::TempDir() + "mission_cli_" + name; }

TEST(MissionCli, ConvertReadsAFolderAsOneMission) {
  const auto r = runCli("convert --log " + data("seaexplorer").string() + " --out " + tmp("sx.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("11 rows"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("SeaExplorer raw"), std::string::npos) << r.out;
  const MissionLog log = readInterchangeCsv(tmp("sx.csv"));
  EXPECT_EQ(log.rowCount(), 11u);
  EXPECT_EQ(log.channel("yo_number").validCount(), 6u);  // 4 + 2 navigation rows
  EXPECT_EQ(*log.metadataValue("mission_files_skipped"), "deployment.yml");
}

TEST(MissionCli, RepeatedLogFlagsAreMerged) {
  const auto r = runCli("convert --log " + data("mission/part_a.csv").string() + " --log " +
                        data("mission/part_b.csv").string() + " --out " + tmp("ab.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("6 rows"), std::string::npos) << r.out;  // 0 10 20 25 30 40
  // The overlap is said once, for the mission.
  EXPECT_NE(r.out.find("1 x time not increasing"), std::string::npos) << r.out;
  EXPECT_EQ(readInterchangeCsv(tmp("ab.csv")).rowCount(), 6u);
}

TEST(MissionCli, MissingFolderIsAClearError) {
  const auto r = runCli("analyze --vehicle slocum_g2 --log " + tmp("no_such_folder"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("No such file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no_such_folder"), std::string::npos) << r.err;
}

// analyze on the raw folder and on the CSV made from it: same segments and
// nearly the same answer (the raw folder has no derived salinity/density
// columns, so the analysis derives its water itself).
void expectSameAnalysis(const fs::path& folder, const fs::path& csv, bool clean_import = true) {
  if (!fs::exists(folder)) GTEST_SKIP() << folder << " not present (shared data folder missing); skipping";
  const auto a = runCli("analyze --vehicle slocum_g2 --log " + folder.string() + " --json -");
  const auto b = runCli("analyze --vehicle slocum_g2 --log " + csv.string() + " --json -");
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(ja["log"], folder.filename().string());
  ASSERT_FALSE(ja["net_buoyancy_kg"].is_null()) << a.out.substr(0, 2000);
  EXPECT_EQ(ja["segments"].size(), jb["segments"].size());
  EXPECT_NEAR(ja["net_buoyancy_kg"].get<double>(), jb["net_buoyancy_kg"].get<double>(), 0.02);
  if (clean_import) {
    EXPECT_TRUE(ja["details"].find("import") == ja["details"].end()) << ja["details"]["import"].dump();
  } else if (ja["details"].contains("import")) {
    // Only what the glider itself wrote (inf in m_time_til_wpt) may be
    // reported; the flight and science files must merge into one channel
    // per sensor even where they spell its unit in another letter case.
    const std::string summary = ja["details"]["import"]["summary"];
    EXPECT_EQ(summary.find("duplicate column"), std::string::npos) << summary.substr(0, 1500);
  }
}

TEST(MissionCli, AnalyzeSeaExplorerRawFolder) {
  expectSameAnalysis(real("seaexplorer-sea046-calvert-2020/raw"),
                     real("seaexplorer-sea046-calvert-2020/sea046-m45-yos10-14.csv"));
}

TEST(MissionCli, AnalyzeSeagliderDiveFolder) {
  expectSameAnalysis(real("seaglider-sg171-bay-of-bengal-2024/raw"),
                     real("seaglider-sg171-bay-of-bengal-2024/sg171-dives100-109.csv"));
}

// The Slocum flight's own binary files (.dbd + .ebd segments and their
// sensor-list caches) give the answer the dbd2asc-made CSV gives.
TEST(MissionCli, AnalyzeSlocumRawFolderLikeItsCsv) {
  expectSameAnalysis(real("slocum-comet-baltic-2016/raw"), real("slocum-comet-baltic-2016/comet-2016-174-05.csv"),
                     /*clean_import=*/false);
}

}  // namespace
}  // namespace auv
