// The SeaExplorer raw reader on hand-written files (tests/data/missionlog/
// seaexplorer, gzip made with Python's gzip module) and on damaged variants
// made here with zlib. Expected values are worked out by hand from the file
// text: NMEA 5142.300 = 51 deg + 42.300/60, 36.2 mS/cm = 3.62 S/m, etc.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/input_error.h"
#include "gzip_test_bytes.h"
#include "missionlog/detail/seaexplorer_rows.h"
#include "missionlog/log_reader.h"
#include "missionlog/seaexplorer_raw_reader.h"

namespace auv {
namespace {
namespace fs = std::filesystem;
using testing::gzipBytes;

fs::path fixture(const std::string& name) { return fs::path(AUV_TEST_DATA_DIR) / "missionlog" / "seaexplorer" / name; }

std::string bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void expectBalanced(const ReadReport& r) {
  EXPECT_EQ(r.data_lines, r.rows_kept + r.rows_skipped + r.rows_merged) << r.summary();
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string allProblems(const ReadReport& r) {
  std::string s;
  for (const auto& p : r.problems) s += p.text() + "\n";
  return s;
}

const std::string kGliHeader =
    "Timestamp;NavState;Heading;Pitch;Roll;Depth;Lat;Lon;BallastPos;LinPos;Altitude;\n";

// n navigation rows, one every 10 s from 01/02/2021 10:00:00.
std::string gliRows(int n) {
  std::string s = kGliHeader;
  for (int i = 0; i < n; ++i) {
    char line[200];
    std::snprintf(line, sizeof line, "01/02/2021 %02d:%02d:%02d;100;%d.5;-20.0;0.5;%d.0;5142.360;-12813.510;-250.0;59.0;-1.0;\n",
                  10 + i * 10 / 3600, (i * 10 / 60) % 60, (i * 10) % 60, i % 360, i);
    s += line;
  }
  return s;
}

TEST(SeaExplorerRaw, NavigationFileMapsItsColumns) {
  ReadReport r;
  const MissionLog log = SeaExplorerRawReader().read(fixture("sea999.7.gli.sub.3.gz"), {}, r);
  ASSERT_EQ(log.rowCount(), 4u) << r.summary();
  EXPECT_TRUE(r.clean()) << r.summary();
  expectBalanced(r);
  EXPECT_EQ(*log.metadataValue("start"), "2021-02-01T10:00:00.000Z");
  EXPECT_EQ(*log.metadataValue("vehicle"), "SeaExplorer sea999");
  EXPECT_EQ(log.time, (std::vector<double>{0, 10, 20, 30}));
  EXPECT_EQ(log.channel("heading").values[0], 359.5);
  EXPECT_EQ(log.channel("heading").unit, "deg");
  EXPECT_EQ(log.channel("pitch").values[0], -40.0);
  EXPECT_EQ(log.channel("depth").values[3], 5.0);
  EXPECT_EQ(log.channel("pump_volume").values[0], 480.0);
  EXPECT_EQ(log.channel("pump_volume").unit, "cm3");
  EXPECT_EQ(log.channel("pump_volume_cmd").values[2], -250.0);
  EXPECT_EQ(log.channel("battery_position").values[2], 70.0);
  EXPECT_EQ(log.channel("battery_position").unit, "mm");
  EXPECT_EQ(log.channel("battery_position_cmd").values[2], 59.0);
  EXPECT_EQ(log.channel("roll_mass").values[3], -9.5);
  EXPECT_EQ(log.channel("roll_mass_cmd").values[3], -10.0);
  EXPECT_EQ(log.channel("heading_cmd").values[0], 270.0);
  EXPECT_EQ(log.channel("nav_state").values[2], 110.0);
  EXPECT_EQ(log.channel("internal_pressure").values[0], 75000.0);
  EXPECT_EQ(log.channel("internal_pressure").unit, "Pa");
  EXPECT_EQ(log.channel("internal_temperature").values[2], 12.1);
  EXPECT_EQ(log.channel("battery_voltage").values[0], 29.1);
  EXPECT_EQ(log.channel("declination").values[0], 17.0);
  EXPECT_EQ(log.channel("yo_number").values[1], 3.0);
  // Altitude -1 = no bottom detection.
  EXPECT_TRUE(std::isnan(log.channel("altitude").values[0]));
  EXPECT_EQ(log.channel("altitude").values[3], 35.5);
  // A GPS fix: at the surface (NavState 116) where the position changed.
  EXPECT_NEAR(log.channel("gps_lat").values[0], 51.0 + 42.300 / 60.0, 1e-12);
  EXPECT_NEAR(log.channel("gps_lon").values[0], -(128.0 + 13.450 / 60.0), 1e-12);
  EXPECT_NEAR(log.channel("gps_lat").values[1], 51.0 + 42.360 / 60.0, 1e-12);
  EXPECT_TRUE(std::isnan(log.channel("gps_lat").values[2]));  // diving: the last fix repeated
  EXPECT_EQ(log.channel("gps_lat").validCount(), 2u);
  ReadReport m;
  const MissionLog fromMemory = parseSeaExplorerRaw(bytesOf(fixture("sea999.7.gli.sub.3.gz")), "sea999.7.gli.sub.3.gz", {}, m);
  EXPECT_EQ(fromMemory.time, log.time);
  EXPECT_EQ(fromMemory.channel("yo_number").values, log.channel("yo_number").values);
}

TEST(SeaExplorerRaw, PayloadRowsArePutInOrderAndNavigationCopiesDropped) {
  ReadReport r;
  const MissionLog log = SeaExplorerRawReader().read(fixture("sea999.7.pld1.raw.3.gz"), {}, r);
  // Five records: one carries only NAV_* (not a sample), one arrived 0.35 s late.
  EXPECT_EQ(r.data_lines, 4);
  EXPECT_TRUE(r.clean()) << r.summary();
  expectBalanced(r);
  EXPECT_EQ(*log.metadataValue("start"), "2021-02-01T10:00:20.900Z");
  ASSERT_EQ(log.rowCount(), 4u);
  // Epoch seconds in a double resolve 0.24 us, so times agree to 1 us.
  EXPECT_NEAR(log.time[1], 0.35, 1e-6);
  EXPECT_NEAR(log.time[3], 9.1, 1e-6);
  EXPECT_EQ(log.channel("pressure").values[0], 1.20);
  EXPECT_EQ(log.channel("pressure").values[1], 1.50);
  EXPECT_EQ(log.channel("conductivity").values[2], 3.62);
  EXPECT_EQ(log.channel("conductivity").unit, "S/m");
  EXPECT_EQ(log.channel("temperature").values[3], 13.6);
  EXPECT_FALSE(log.has("depth"));      // NAV_DEPTH is the gli's Depth, not imported twice
  EXPECT_FALSE(log.has("nav_depth"));
  EXPECT_FALSE(log.has("gpctd_dof"));  // never sampled
}

TEST(SeaExplorerRaw, LegatoConductivityIsConverted) {
  ReadReport r;
  const MissionLog log = SeaExplorerRawReader().read(fixture("sea999.7.pld1.raw.4.gz"), {}, r);
  EXPECT_TRUE(r.clean()) << r.summary();
  EXPECT_DOUBLE_EQ(log.channel("conductivity").values[0], 3.62);  // 36.2 mS/cm
  EXPECT_EQ(log.channel("conductivity").source_unit, "mS/cm");
  EXPECT_EQ(log.channel("salinity").values[1], 33.0);
  EXPECT_EQ(log.channel("pressure").values[1], 11.7);
}

TEST(SeaExplorerRaw, RegistryPicksItByContent) {
  const LogReaderRegistry reg = LogReaderRegistry::withBuiltinReaders();
  for (const char* f : {"sea999.7.gli.sub.3.gz", "sea999.7.pld1.raw.4.gz"}) {
    const LogReader* r = reg.find(fixture(f));
    ASSERT_NE(r, nullptr) << f;
    EXPECT_EQ(r->formatName(), SeaExplorerRawReader().formatName());
  }
  // gzip of some other text, and the plain table, by content.
  const SeaExplorerRawReader sx;
  EXPECT_FALSE(sx.canRead("x.gz", gzipBytes("time [s],depth [m]\n0,1\n")));
  EXPECT_TRUE(sx.canRead("x.txt", gliRows(2)));
  EXPECT_FALSE(reg.find(fixture("deployment.yml")) && reg.find(fixture("deployment.yml"))->formatName() ==
                                                           SeaExplorerRawReader().formatName());
}

TEST(SeaExplorerRaw, PlainTextReadsLikeGzip) {
  const std::string text = gliRows(30);
  ReadReport a, b;
  const MissionLog plain = parseSeaExplorerRaw(text, "sea1.2.gli.sub.5", {}, a);
  const MissionLog gz = parseSeaExplorerRaw(gzipBytes(text), "sea1.2.gli.sub.5.gz", {}, b);
  ASSERT_EQ(plain.rowCount(), 30u);
  EXPECT_EQ(plain.time, gz.time);
  EXPECT_EQ(plain.channel("depth").values, gz.channel("depth").values);
  EXPECT_EQ(plain.channel("yo_number").values[0], 5.0);
  EXPECT_EQ(plain.time.back(), 290.0);
}

TEST(SeaExplorerRaw, TruncatedGzipKeepsTheRowsBeforeTheCut) {
  const std::string gz = gzipBytes(gliRows(400));
  const std::string cut = gz.substr(0, gz.size() / 2);
  ReadReport r;
  const MissionLog log = parseSeaExplorerRaw(cut, "sea1.2.gli.sub.5.gz", {}, r);
  EXPECT_GT(log.rowCount(), 20u);
  EXPECT_LT(log.rowCount(), 400u);
  EXPECT_GE(r.count(ReadProblemKind::kTruncatedLine), 1);
  expectBalanced(r);
  const std::string all = allProblems(r);
  EXPECT_TRUE(contains(all, "sea1.2.gli.sub.5.gz")) << all;
  EXPECT_TRUE(contains(all, "ends early (file cut short) at compressed byte " + std::to_string(cut.size()))) << all;
  EXPECT_TRUE(contains(all, "copy the file again")) << all;
  // Rows are whole: the depth of row i is i.
  const auto& depth = log.channel("depth").values;
  for (std::size_t i = 0; i < depth.size(); ++i) EXPECT_EQ(depth[i], static_cast<double>(i));
}

TEST(SeaExplorerRaw, DamagedGzipIsReportedOrRefusedWithItsPosition) {
  std::string gz = gzipBytes(gliRows(400));
  for (std::size_t i = gz.size() / 2; i < gz.size() / 2 + 16; ++i) gz[i] = static_cast<char>(gz[i] ^ 0x5a);
  ReadReport r;
  try {
    const MissionLog log = parseSeaExplorerRaw(gz, "d.gz", {}, r);
    EXPECT_LT(log.rowCount(), 400u);
    EXPECT_GE(r.totalProblems(), 1);
    EXPECT_TRUE(contains(allProblems(r), "compressed byte")) << allProblems(r);
    expectBalanced(r);
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "d.gz")) << e.what();
  }
  // Damage in the first bytes after the header: nothing to keep, refused.
  std::string early = gzipBytes(gliRows(10));
  for (std::size_t i = 10; i < early.size(); ++i) early[i] = '\xff';
  try {
    parseSeaExplorerRaw(early, "e.gz", {}, r);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "e.gz")) << e.what();
    EXPECT_TRUE(contains(e.what(), "compressed byte")) << e.what();
  }
}

TEST(SeaExplorerRaw, HostileGzipIsRefused) {
  // 8 MiB of one repeated row compress to a few kB: refused above the limit.
  std::string big = kGliHeader;
  const std::string row = "01/02/2021 10:00:00;100;1;1;1;1;1;1;1;1;1;\n";
  while (big.size() < (std::size_t{8} << 20)) big += row;
  const std::string gz = gzipBytes(big);
  ASSERT_LT(gz.size(), std::size_t{100} << 10);
  ReadReport r;
  try {
    parseSeaExplorerRaw(gz, "bomb.gz", {}, r, std::size_t{1} << 20);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "bomb.gz")) << e.what();
    EXPECT_TRUE(contains(e.what(), "decompresses to more than 1 MiB")) << e.what();
  }
}

TEST(SeaExplorerRaw, DamagedRowsAreSkippedAndCounted) {
  const std::string text = kGliHeader +
                           "01/02/2021 10:00:00;100;1;-20;0;1.0;5142.3;-12813.4;-250;59;-1;\n"
                           "01/02/2021 10:00:10;100;1;-20;0;2.0;5142.3;-12813.4;-250;59;\n"        // a cell short
                           "01/02/2021 10:00:20;100;1;-20;0;x.0;5142.3;-12813.4;-250;59;-1;\n"     // not a number
                           "32/02/2021 10:00:30;100;1;-20;0;4.0;5142.3;-12813.4;-250;59;-1;\n"     // no such day
                           ";100;1;-20;0;5.0;5142.3;-12813.4;-250;59;-1;\n"                        // no time
                           "01/02/2021 10:00:50;100;1;-20;0;6.0;5142.3;-12813.4;-250;59;-1;\n"
                           "01/02/2021 10:01:00;100;1;-20;0;7.0;5142.3;-12813.4;-250;59;-1;\n";
  ReadReport r;
  const MissionLog log = parseSeaExplorerRaw(text, "rows.gli", {}, r);
  EXPECT_EQ(log.channel("depth").values, (std::vector<double>{1.0, 6.0, 7.0}));
  EXPECT_EQ(r.rows_skipped, 4);
  EXPECT_EQ(r.count(ReadProblemKind::kWrongCellCount), 1);
  EXPECT_EQ(r.count(ReadProblemKind::kNotANumber), 2);
  EXPECT_EQ(r.count(ReadProblemKind::kMissingTime), 1);
  expectBalanced(r);
  const std::string all = allProblems(r);
  EXPECT_TRUE(contains(all, "rows.gli:3: 10 cells where the header has 11")) << all;
  EXPECT_TRUE(contains(all, "rows.gli:4:6: depth: 'x.0' is not a number")) << all;
  EXPECT_TRUE(contains(all, "rows.gli:5:1: time: '32/02/2021 10:00:30' is not a time")) << all;
}

TEST(SeaExplorerRaw, ClockJumpsBackAreNotSortedAway) {
  // A step back of an hour is a clock jump, not arrival jitter: the common
  // time-order repair drops and reports it.
  const std::string text = kGliHeader +
                           "01/02/2021 10:00:00;100;1;-20;0;1.0;5142.3;-12813.4;-250;59;-1;\n"
                           "01/02/2021 10:00:10;100;1;-20;0;2.0;5142.3;-12813.4;-250;59;-1;\n"
                           "01/02/2021 09:00:20;100;1;-20;0;3.0;5142.3;-12813.4;-250;59;-1;\n"
                           "01/02/2021 10:00:30;100;1;-20;0;4.0;5142.3;-12813.4;-250;59;-1;\n";
  ReadReport r;
  const MissionLog log = parseSeaExplorerRaw(text, "jump.gli", {}, r);
  EXPECT_EQ(log.channel("depth").values, (std::vector<double>{1.0, 2.0, 4.0}));
  EXPECT_EQ(r.count(ReadProblemKind::kTimeNotIncreasing), 1);
  expectBalanced(r);
}

TEST(SeaExplorerRaw, RefusesWhatIsNotASeaExplorerFile) {
  ReadReport r;
  auto refusal = [&](std::string_view bytes) -> std::string {
    try {
      parseSeaExplorerRaw(bytes, "x.gz", {}, r);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_TRUE(contains(refusal(""), "empty")) << refusal("");
  EXPECT_TRUE(contains(refusal(gzipBytes("")), "empty")) << refusal(gzipBytes(""));
  EXPECT_TRUE(contains(refusal("a,b,c\n1,2,3\n"), "not a `;`-separated SeaExplorer header"));
  EXPECT_TRUE(contains(refusal("Depth;Pitch;\n1;2;\n"), "no time column"));
  EXPECT_TRUE(contains(refusal(kGliHeader), "no usable data rows"));
  EXPECT_TRUE(contains(refusal(std::string("\x1f\x8b\x08", 3)), "x.gz"));
}

TEST(SeaExplorerRaw, TimeFormats) {
  double t = 0;
  ASSERT_TRUE(detail::parseSeaExplorerTime("08/09/2020 17:46:17.852", t));
  EXPECT_DOUBLE_EQ(t, 1599587177.852);  // date -u -d '2020-09-08 17:46:17' +%s = 1599587177
  ASSERT_TRUE(detail::parseSeaExplorerTime("08/09/2020 17:45:56", t));
  EXPECT_EQ(t, 1599587156.0);
  ASSERT_TRUE(detail::parseSeaExplorerTime("2020-09-08T17:45:56Z", t));
  EXPECT_EQ(t, 1599587156.0);
  ASSERT_TRUE(detail::parseSeaExplorerTime("08.09.2020 17:45:56", t));
  EXPECT_EQ(t, 1599587156.0);
  EXPECT_FALSE(detail::parseSeaExplorerTime("08/09/2020 25:45:56", t));
  EXPECT_FALSE(detail::parseSeaExplorerTime("08/09/2020 17:45:56.", t));
  EXPECT_FALSE(detail::parseSeaExplorerTime("8/9/2020 17:45:56", t));
}

}  // namespace
}  // namespace auv
