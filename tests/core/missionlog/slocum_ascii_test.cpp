// Slocum dbd2asc output. The fixtures are written by hand from the format
// (header tags, three label lines, NaN-padded rows) with Slocum sensor names
// and realistic values; the equivalent interchange CSV of the same data,
// with the Slocum units in its header, is the oracle for the conversions.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "common/input_error.h"
#include "missionlog/interchange_csv.h"
#include "missionlog/slocum_ascii_reader.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

fs::path fixture(const std::string& name) { return fs::path(AUV_TEST_DATA_DIR) / "missionlog" / name; }
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

bool sameValues(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!((std::isnan(a[i]) && std::isnan(b[i])) || a[i] == b[i])) return false;
  return true;
}

void expectBalanced(const ReadReport& r) {
  EXPECT_EQ(r.data_lines, r.rows_kept + r.rows_skipped + r.rows_merged) << r.summary();
}

std::string refusal(const std::string& name) {
  ReadReport r;
  try {
    readSlocumAscii(fixture(name), {}, r);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << " was accepted";
  return {};
}

TEST(SlocumAscii, MergedEngineeringAndScienceRowsMatchTheEquivalentCsv) {
  ReadReport r, rc;
  const MissionLog log = readSlocumAscii(fixture("slocum_merged.dba"), {}, r);
  const MissionLog csv = readInterchangeCsv(fixture("slocum_merged_equivalent.csv"), {}, rc);
  ASSERT_TRUE(rc.clean()) << rc.summary();
  EXPECT_TRUE(r.clean()) << r.summary();
  // 9 rows in the file; the science row at 1700000008.5 shares its time with
  // an engineering row and is merged into it. The science row at 14.5 s comes
  // after the engineering row at 17 s in the file but is in order within its
  // own stream, so nothing is dropped.
  EXPECT_EQ(r.data_lines, 9);
  EXPECT_EQ(r.rows_merged, 1);
  expectBalanced(r);
  EXPECT_EQ(log.time, csv.time);
  EXPECT_EQ(*log.metadataValue("start"), *csv.metadataValue("start"));
  ASSERT_EQ(log.channels.size(), csv.channels.size());
  for (const auto& c : csv.channels) {
    const LogChannel* s = log.find(c.name);
    ASSERT_NE(s, nullptr) << c.name;
    EXPECT_EQ(s->unit, c.unit) << c.name;
    for (std::size_t i = 0; i < log.rowCount(); ++i) {
      const double a = s->values[i], b = c.values[i];
      if (std::isnan(b)) EXPECT_TRUE(std::isnan(a)) << c.name << " row " << i;
      else EXPECT_NEAR(a, b, 1e-12 * std::max(1.0, std::fabs(b))) << c.name << " row " << i;
    }
  }
  // Spot values against the unit definitions.
  EXPECT_DOUBLE_EQ(log.channel("pitch").values[1], -0.384 * kDegPerRad);
  EXPECT_DOUBLE_EQ(log.channel("battery_position").values[1], 0.37 * 25.4);  // in -> mm
  EXPECT_DOUBLE_EQ(log.channel("pressure").values[2], 6.12);                // 0.612 bar
  EXPECT_DOUBLE_EQ(log.channel("m_gps_lat").values[0], 54.0 + 44.7282 / 60.0);  // ddmm.mmmm
  EXPECT_TRUE(std::isnan(log.channel("m_gps_lat").values[3]));             // 69696969 = no fix
  EXPECT_EQ(log.channel("m_vacuum").unit, "inHg");                          // other sensors as written
  EXPECT_EQ(log.channel("temperature").source_unit, "degc");
  // m_ballast_pumped competes with m_de_oil_vol for pump_volume and was never
  // sampled: m_de_oil_vol wins and the empty sensor is left out.
  EXPECT_EQ(log.channel("pump_volume").values[0], -260.0);
  EXPECT_FALSE(log.has("m_ballast_pumped"));
  EXPECT_EQ(*log.metadataValue("sensors_never_sampled"), "1 (not imported)");
  EXPECT_EQ(*log.metadataValue("glider"), "ammonite");
  EXPECT_EQ(*log.metadataValue("mission_name"), "YO10.MI");
}

TEST(SlocumAscii, ShallowGliderWithBallastPumpAndFillValues) {
  ReadReport r;
  const MissionLog log = readSlocumAscii(fixture("slocum_shallow.asc"), {}, r);
  ASSERT_EQ(log.rowCount(), 6u);
  EXPECT_EQ(*log.metadataValue("start"), "2016-06-23T17:51:11.771Z");
  EXPECT_EQ(log.time.front(), 0.0);
  EXPECT_NEAR(log.time.back(), 1466704293.377 - 1466704271.771, 1e-6);
  EXPECT_EQ(log.channel("pump_volume").values[0], 233.0);  // m_ballast_pumped
  EXPECT_EQ(log.channel("pump_volume_cmd").values[1], -233.0);
  EXPECT_TRUE(std::isnan(log.channel("pump_volume_cmd").values[2]));
  EXPECT_DOUBLE_EQ(log.channel("roll").values[0], 0.0611 * kDegPerRad);
  EXPECT_EQ(log.channel("m_water_depth").values[0], -1.0);  // Slocum's placeholder, kept as logged
  EXPECT_TRUE(std::isnan(log.channel("m_water_depth").values[1]));  // inf
  EXPECT_EQ(r.cells_blanked, 1);
  EXPECT_EQ(r.count(ReadProblemKind::kValueOutOfRange), 1);
  EXPECT_EQ(log.channel("m_coulomb_current").unit, "amp");
  EXPECT_EQ(*log.metadataValue("segment_filename_1"), "comet-2016-174-5-1");
  EXPECT_EQ(*log.metadataValue("glider"), "comet");
}

TEST(SlocumAscii, DamagedRowsAreSkippedAndCounted) {
  ReadReport r;
  const MissionLog log = readSlocumAscii(fixture("bad_slocum_rows.dba"), {}, r);
  ASSERT_EQ(log.rowCount(), 4u) << r.summary();
  EXPECT_EQ(r.data_lines, 10);
  EXPECT_EQ(r.rows_skipped, 5);
  EXPECT_EQ(r.rows_merged, 1);
  expectBalanced(r);
  EXPECT_EQ(r.count(ReadProblemKind::kWrongCellCount), 2);  // 7 values; binary junk
  EXPECT_EQ(r.count(ReadProblemKind::kNotANumber), 1);      // 1.2.3
  EXPECT_EQ(r.count(ReadProblemKind::kTimeNotIncreasing), 1);
  EXPECT_EQ(r.count(ReadProblemKind::kTruncatedLine), 1);
  EXPECT_EQ(r.count(ReadProblemKind::kDuplicateTime), 1);
  // The duplicate filled the water depth its twin had not sampled.
  EXPECT_EQ(log.channel("m_water_depth").values[2], 62.6);
  std::string all;
  for (const auto& p : r.problems) all += p.text() + "\n";
  EXPECT_TRUE(contains(all, "bad_slocum_rows.dba:21:45: m_battpos: '1.2.3' is not a number")) << all;
  EXPECT_TRUE(contains(all, "bad_slocum_rows.dba:24: time: time 2013-04-23T08:04:49.061Z breaks the increasing order")) << all;
  EXPECT_TRUE(contains(all, ":28:")) << all;  // the cut-off last line
}

TEST(SlocumAscii, MissingBytesLineIsRecovered) {
  ReadReport a, b;
  const MissionLog good = readSlocumAscii(fixture("slocum_shallow.asc"), {}, a);
  const MissionLog log = readSlocumAscii(fixture("bad_slocum_no_bytes_line.dba"), {}, b);
  EXPECT_EQ(log.time, good.time);
  for (const auto& c : good.channels) EXPECT_TRUE(sameValues(c.values, log.channel(c.name).values)) << c.name;
  EXPECT_TRUE(contains(*log.metadataValue("note"), "bytes label line is missing"));
}

TEST(SlocumAscii, RefusesWhatCannotBeRead) {
  EXPECT_TRUE(contains(refusal("bad_slocum_truncated_header.dba"), "ends inside the header tags"));
  EXPECT_TRUE(contains(refusal("bad_slocum_no_labels.dba"), "holds numbers, not sensor names"));
  EXPECT_TRUE(contains(refusal("bad_slocum_no_time.dba"), "none of the 2 sensors is m_present_time"));
  EXPECT_TRUE(contains(refusal("hugin_depth.txt"), "does not start with `dbd_label:`"));
  EXPECT_TRUE(contains(refusal("bad_empty.csv"), "the file is empty"));
  EXPECT_TRUE(contains(refusal("missing.dba"), "cannot open"));
}

TEST(SlocumAscii, SmallBlocksAndMemoryGiveTheSameLog) {
  ReadReport a, b;
  const MissionLog big = readSlocumAscii(fixture("slocum_merged.dba"), {}, a);
  ReadOptions o;
  o.block_bytes = 64;  // shorter than the label line: it is skipped, and the file refused
  EXPECT_THROW(readSlocumAscii(fixture("slocum_merged.dba"), o, b), InputError);
  o.block_bytes = 256;
  const MissionLog small = readSlocumAscii(fixture("slocum_merged.dba"), o, b);
  EXPECT_EQ(big.time, small.time);
  for (const auto& c : big.channels) EXPECT_TRUE(sameValues(c.values, small.channel(c.name).values)) << c.name;
}

}  // namespace
}  // namespace auv
