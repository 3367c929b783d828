// Whole missions through readMission: folders expanded, non-log files
// skipped, files merged on time, overlaps and gaps noted once. Fixtures:
// tests/data/missionlog/mission (three interchange CSV parts: b overlaps a by
// 5 s, c starts 2 h later) and tests/data/missionlog/seaexplorer (two yos of
// gli+pld1 with different column sets, and a deployment.yml). Expected rows
// are the union of the time stamps written in the files, worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "common/input_error.h"
#include "missionlog/detail/mission_groups.h"
#include "missionlog/mission_files.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

fs::path data(const std::string& rel) { return fs::path(AUV_TEST_DATA_DIR) / "missionlog" / rel; }

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string allProblems(const ReadReport& r) {
  std::string s;
  for (const auto& p : r.problems) s += p.text() + "\n";
  return s;
}

TEST(MissionFiles, PartsMergeOnTimeWithOverlapAndGapNotedOnce) {
  ReadReport r;
  const MissionLog log = readMission({data("mission/part_a.csv"), data("mission/part_b.csv"),
                                      data("mission/part_c.csv")}, {}, r);
  // a: 0 10 20 30, b: 25 30 40, c: 7200 7210 (s after 10:00:00).
  EXPECT_EQ(log.time, (std::vector<double>{0, 10, 20, 25, 30, 40, 7200, 7210}));
  EXPECT_EQ(*log.metadataValue("start"), "2021-02-01T10:00:00.000Z");
  EXPECT_EQ(log.channel("depth").values, (std::vector<double>{1, 2, 3, 3.5, 4, 5, 6, 7}));
  EXPECT_EQ(log.channel("pitch").values[4], -23.0);  // a and b agree at 30 s
  EXPECT_EQ(log.channel("temperature").validCount(), 2u);
  EXPECT_TRUE(std::isnan(log.channel("temperature").values[0]));
  EXPECT_EQ(r.rows_kept, 8);
  EXPECT_EQ(r.rows_merged, 1);
  EXPECT_EQ(r.data_lines, 9);
  EXPECT_EQ(r.count(ReadProblemKind::kTimeNotIncreasing), 1);
  EXPECT_EQ(r.count(ReadProblemKind::kTimeGap), 1);
  EXPECT_EQ(r.count(ReadProblemKind::kConflictingDuplicate), 0);
  EXPECT_EQ(r.totalProblems(), 2);
  const std::string all = allProblems(r);
  EXPECT_TRUE(contains(all, "1 of 3 files overlap in time with an earlier file of the same kind (5 s in all; first: part_b.csv starts "
                            "before part_a.csv ends)"))
      << all;
  EXPECT_TRUE(contains(all, "1 gap between files longer than 600 s (largest 7160 s, between part_b.csv and part_c.csv)"))
      << all;
  EXPECT_EQ(*log.metadataValue("mission_files"), "3 files: part_a.csv, part_b.csv, part_c.csv");
}

TEST(MissionFiles, DisagreeingValuesAtOneTimeAreNotedOncePerChannel) {
  const fs::path dir = fs::path(::testing::TempDir()) / "mission_conflict";
  fs::create_directories(dir);
  for (int k = 0; k < 3; ++k) {
    std::ofstream(dir / ("seg" + std::to_string(k) + ".csv"))
        << "# start: 2021-02-01T10:00:00.000Z\ntime [s],depth [m]\n0," << k << "\n10," << k << "\n";
  }
  ReadReport r;
  const MissionLog log = readMission({dir}, {}, r);
  EXPECT_EQ(log.channel("depth").values, (std::vector<double>{0, 0}));  // the first file's kept
  EXPECT_EQ(r.count(ReadProblemKind::kConflictingDuplicate), 1);
  EXPECT_TRUE(contains(allProblems(r), "4 values differ from an earlier file's")) << allProblems(r);
  fs::remove_all(dir);
}

TEST(MissionFiles, SeaExplorerFolderIsOneMission) {
  ReadReport r;
  const MissionLog log = readMission({data("seaexplorer")}, {}, r);
  EXPECT_TRUE(r.clean()) << r.summary();
  EXPECT_EQ(r.data_lines, r.rows_kept + r.rows_skipped + r.rows_merged);
  // gli 3: 0 10 20 30; pld1 3: 20.9 21.25 22.25 30; gli 4: 40 50; pld1 4: 41 51.
  const std::vector<double> t{0, 10, 20, 20.9, 21.25, 22.25, 30, 40, 41, 50, 51};
  ASSERT_EQ(log.rowCount(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(log.time[i], t[i], 1e-6) << i;  // epoch doubles: 0.24 us
  EXPECT_EQ(r.rows_merged, 1);  // 30 s: a gli row and a payload row
  EXPECT_EQ(*log.metadataValue("start"), "2021-02-01T10:00:00.000Z");
  EXPECT_EQ(*log.metadataValue("mission_files_skipped"), "deployment.yml");
  EXPECT_EQ(log.channel("depth").values[6], 5.0);
  EXPECT_EQ(log.channel("pressure").values[6], 4.8);  // the payload row at 30 s
  EXPECT_EQ(log.channel("pressure").values[3], 1.2);
  EXPECT_DOUBLE_EQ(log.channel("conductivity").values[8], 3.62);  // yo 4: Legato 36.2 mS/cm
  EXPECT_EQ(log.channel("yo_number").values[0], 3.0);
  EXPECT_EQ(log.channel("yo_number").values[7], 4.0);
  EXPECT_TRUE(std::isnan(log.channel("yo_number").values[3]));
  EXPECT_EQ(log.channel("security_level").validCount(), 4u);  // yo 3 only
  EXPECT_EQ(log.channel("deadreckoning").values[9], 1.0);       // yo 4 only
  EXPECT_EQ(log.channel("battery_position").values[9], 41.0);
  EXPECT_EQ(log.channel("gps_lat").validCount(), 2u);
}

TEST(MissionFiles, RepeatedFilesReadLikeTheFolder) {
  ReadReport a, b;
  const MissionLog folder = readMission({data("seaexplorer")}, {}, a);
  const MissionLog files = readMission({data("seaexplorer/sea999.7.pld1.raw.4.gz"), data("seaexplorer/sea999.7.gli.sub.3.gz"),
                                        data("seaexplorer/sea999.7.gli.sub.4.gz"), data("seaexplorer/sea999.7.pld1.raw.3.gz")},
                                       {}, b);
  EXPECT_EQ(folder.time, files.time);
  ASSERT_EQ(folder.channels.size(), files.channels.size());
  for (const auto& c : folder.channels) {
    const auto* d = files.find(c.name);
    ASSERT_NE(d, nullptr) << c.name;
    for (std::size_t i = 0; i < c.values.size(); ++i)
      EXPECT_TRUE((std::isnan(c.values[i]) && std::isnan(d->values[i])) || c.values[i] == d->values[i]) << c.name;
  }
  EXPECT_TRUE(b.clean()) << b.summary();
}

TEST(MissionFiles, OneFileIsReadAsTheRegistryReadsIt) {
  ReadReport a, b;
  const MissionLog one = readMission({data("mission/part_a.csv")}, {}, a);
  const MissionLog direct = LogReaderRegistry::withBuiltinReaders().read(data("mission/part_a.csv"), {}, b);
  EXPECT_EQ(one.time, direct.time);
  EXPECT_EQ(one.metadata.size(), direct.metadata.size());
  EXPECT_EQ(one.metadataValue("mission_files"), nullptr);
}

TEST(MissionFiles, RefusesWhatCannotBeAMission) {
  auto refusal = [](std::vector<fs::path> in) -> std::string {
    ReadReport r;
    try {
      readMission(in, {}, r);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string missing = refusal({data("mission/part_a.csv"), data("mission/nope.csv")});
  EXPECT_TRUE(contains(missing, "nope.csv")) << missing;
  EXPECT_TRUE(contains(missing, "no such file or folder")) << missing;
  const fs::path empty = fs::path(::testing::TempDir()) / "mission_empty";
  fs::create_directories(empty);
  std::ofstream(empty / "notes.md") << "# nothing\n";
  const std::string none = refusal({empty});
  EXPECT_TRUE(contains(none, "holds no file that a reader recognises (skipped: notes.md)")) << none;
  // Absolute and relative time cannot share a time base.
  const fs::path rel = fs::path(::testing::TempDir()) / "mission_relative.csv";
  std::ofstream(rel) << "time [s],depth [m]\n0,1\n1,2\n";
  const std::string mixed = refusal({data("mission/part_a.csv"), rel});
  EXPECT_TRUE(contains(mixed, "relative")) << mixed;
  EXPECT_TRUE(contains(mixed, "mission_relative.csv")) << mixed;
  fs::remove_all(empty);
  fs::remove(rel);
}

TEST(MissionFiles, GroupsFollowTheVendorsNames) {
  using detail::missionGroupKey;
  EXPECT_EQ(missionGroupKey("sea046.45.gli.sub.10.gz"), missionGroupKey("sea046.45.pld1.raw.10.gz"));
  EXPECT_NE(missionGroupKey("sea046.45.gli.sub.10.gz"), missionGroupKey("sea046.45.gli.sub.11.gz"));
  EXPECT_EQ(missionGroupKey("01600001.dbd"), missionGroupKey("01600001.EBD"));
  EXPECT_EQ(missionGroupKey("amadeus-2014-204-05-000.sbd"), missionGroupKey("amadeus-2014-204-05-000.tbd"));
  EXPECT_NE(missionGroupKey("p1710100.nc"), missionGroupKey("p1710101.nc"));
  EXPECT_TRUE(detail::isKnownNonLogFile("sg_calib_constants.m"));
  EXPECT_TRUE(detail::isKnownNonLogFile("deployment.yml"));
  EXPECT_TRUE(detail::isKnownNonLogFile("README.md"));
  EXPECT_TRUE(detail::isKnownNonLogFile("0a1b2c3d.cac"));
  EXPECT_FALSE(detail::isKnownNonLogFile("p1710100.nc"));
  EXPECT_FALSE(detail::isKnownNonLogFile("mission.log"));
}

}  // namespace
}  // namespace auv
