#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include "common/input_error.h"
#include "missionlog/decimal_parse.h"
#include "missionlog/interchange_csv.h"

namespace auv {
namespace {
std::string fixture(const std::string& name) {
  return std::string(AUV_TEST_DATA_DIR) + "/missionlog/" + name;
}
const LogChannel& ch(const MissionLog& log, std::string_view name) { return log.channel(name); }
}  // namespace

TEST(InterchangeCsvRead, MinimalFileKeepsMetadataChannelsAndSparseCells) {
  ReadReport rep;
  const MissionLog log = readInterchangeCsv(fixture("good_minimal.csv"), {}, rep);
  EXPECT_TRUE(rep.clean()) << rep.summary();
  EXPECT_EQ(rep.rows_kept, 5);
  EXPECT_EQ(rep.lines, 11);
  ASSERT_EQ(log.rowCount(), 5u);
  EXPECT_EQ(log.time, (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
  ASSERT_EQ(log.metadata.size(), 5u);
  EXPECT_EQ(*log.metadataValue("vehicle"), "hugin1000");
  EXPECT_EQ(*log.metadataValue("operator_note"), "ballast checked twice: ok");  // unknown key kept
  EXPECT_DOUBLE_EQ(*log.startEpochSeconds(), 1778746320.0);
  ASSERT_EQ(log.channels.size(), 6u);
  EXPECT_EQ(log.channels[5].name, "dive_number");
  EXPECT_EQ(log.channels[5].unit, "1");
  EXPECT_EQ(ch(log, "temperature").validCount(), 3u);
  EXPECT_EQ(ch(log, "speed").validCount(), 2u);  // empty and NaN cells are "not sampled"
  EXPECT_DOUBLE_EQ(ch(log, "pitch").values[3], -4.5);
  EXPECT_EQ(log.series("speed").t, (std::vector<double>{0.5, 1.5}));
}

TEST(InterchangeCsvRead, UnitsInBracketsAreConvertedToCanonicalUnits) {
  ReadReport rep;
  const MissionLog log = readInterchangeCsv(fixture("good_units.csv"), {}, rep);
  EXPECT_TRUE(rep.clean()) << rep.summary();
  EXPECT_EQ(log.time, (std::vector<double>{0.0, 0.5, 1.0}));  // [ms]
  const double kn = 1852.0 / 3600.0;
  EXPECT_NEAR(ch(log, "depth").values[0], 30.48, 1e-12);
  EXPECT_NEAR(ch(log, "depth").values[1], 32.8084 * 0.3048, 1e-12);
  EXPECT_EQ(ch(log, "depth").unit, "m");
  EXPECT_EQ(ch(log, "depth").source_unit, "ft");
  EXPECT_NEAR(ch(log, "pitch").values[0], 30.0, 1e-12);
  EXPECT_NEAR(ch(log, "pitch").values[1], -0.1 * 180.0 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(ch(log, "pitch_cmd").values[0], -30.0, 1e-12);  // _cmd variant converted too
  EXPECT_NEAR(ch(log, "speed").values[0], 10.0 * kn, 1e-12);
  EXPECT_NEAR(ch(log, "temperature").values[0], 100.0, 1e-12);
  EXPECT_NEAR(ch(log, "temperature").values[1], 0.0, 1e-12);
  EXPECT_NEAR(ch(log, "temperature").values[2], 10.0, 1e-12);
  EXPECT_DOUBLE_EQ(ch(log, "pressure").values[0], 10.0);
  EXPECT_DOUBLE_EQ(ch(log, "pressure").values[1], 5.0);
  EXPECT_NEAR(ch(log, "conductivity").values[0], 4.2914, 1e-12);
  EXPECT_DOUBLE_EQ(ch(log, "pump_volume").values[0], 250.0);
  EXPECT_NEAR(ch(log, "pump_volume").values[1], -100.0, 1e-12);
  EXPECT_NEAR(ch(log, "battery_position").values[1], -12.7, 1e-12);
  EXPECT_NEAR(ch(log, "prop_rpm").values[0], 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(ch(log, "power").values[1], 1200.0);
  EXPECT_DOUBLE_EQ(ch(log, "speed_flightmodel").values[0], 0.25);
  EXPECT_DOUBLE_EQ(ch(log, "salinity").values[0], 35.0);
  EXPECT_EQ(ch(log, "salinity").unit, "PSU");
  EXPECT_NEAR(ch(log, "altitude").values[0], 12.34, 1e-12);
  EXPECT_TRUE(std::isnan(ch(log, "altitude").values[1]));
  // Not in the format table: kept as written.
  EXPECT_EQ(ch(log, "internal_pressure").unit, "Pa");
  EXPECT_DOUBLE_EQ(ch(log, "internal_pressure").values[0], 75064.0);
}

TEST(InterchangeCsvRead, BomCrlfQuotesSpacesAndNaSpellings) {
  ReadReport rep;
  const MissionLog log = readInterchangeCsv(fixture("good_crlf_bom.csv"), {}, rep);
  EXPECT_EQ(*log.metadataValue("vehicle"), "delphin2");
  ASSERT_EQ(log.rowCount(), 4u);
  const auto& d = ch(log, "depth").values;
  const auto& r = ch(log, "roll").values;
  EXPECT_DOUBLE_EQ(d[0], 1.5);
  EXPECT_TRUE(std::isnan(d[1]));
  EXPECT_DOUBLE_EQ(d[2], 2.5);
  EXPECT_DOUBLE_EQ(r[0], 0.25);
  EXPECT_DOUBLE_EQ(r[1], -0.5);
  EXPECT_TRUE(std::isnan(r[2]));
  EXPECT_DOUBLE_EQ(r[3], 0.1);
  // The only remark: the last line has no line end (but is complete, so kept).
  EXPECT_EQ(rep.totalProblems(), 1);
  EXPECT_EQ(rep.count(ReadProblemKind::kNoFinalNewline), 1);
  EXPECT_EQ(rep.problems[0].where.line, 7);
}

TEST(InterchangeCsvRead, Iso8601TimeCountsFromStart) {
  ReadReport rep;
  const MissionLog a = readInterchangeCsv(fixture("good_iso8601.csv"), {}, rep);
  EXPECT_TRUE(rep.clean()) << rep.summary();
  ASSERT_EQ(a.rowCount(), 3u);
  EXPECT_NEAR(a.time[1], 0.5, 1e-6);
  EXPECT_NEAR(a.time[2], 1.0, 1e-6);  // 10:12:01+02:00
  EXPECT_EQ(*a.metadataValue("start"), "2026-05-14T08:12:00.000Z");  // added: first row
  EXPECT_EQ(ch(a, "depth").values[2], 1.5);

  const MissionLog b = readInterchangeCsv(fixture("good_iso8601_no_zone.csv"), {}, rep);
  EXPECT_NEAR(b.time[0], 720.0, 1e-6);  // from `# start: 08:00:00Z`
  EXPECT_NEAR(b.time[2], 740.25, 1e-6);
  EXPECT_EQ(rep.count(ReadProblemKind::kTimeZoneAssumed), 1);
  EXPECT_EQ(rep.problems.at(0).where.line, 3);
}

TEST(InterchangeCsvRead, UntidyButUsableFileIsReadWithNotes) {
  ReadReport rep;
  const MissionLog log = readInterchangeCsv(fixture("good_untidy.csv"), {}, rep);
  ASSERT_EQ(log.rowCount(), 3u);
  ASSERT_EQ(log.metadata.size(), 2u);
  EXPECT_EQ(log.metadata[1].key, "");
  EXPECT_EQ(log.metadata[1].value, "free text without a colon");
  ASSERT_EQ(log.channels.size(), 3u);
  EXPECT_EQ(log.channels[0].name, "depth");
  EXPECT_EQ(log.channels[0].unit, "m");  // assumed
  EXPECT_EQ(log.channels[1].name, "depth_2");
  EXPECT_DOUBLE_EQ(log.channels[1].values[2], 12.0);
  EXPECT_EQ(rep.count(ReadProblemKind::kUnitAssumed), 1);
  EXPECT_EQ(rep.count(ReadProblemKind::kDuplicateColumn), 1);
  EXPECT_EQ(rep.count(ReadProblemKind::kColumnIgnored), 1);
  EXPECT_EQ(rep.count(ReadProblemKind::kCommentAfterHeader), 1);
  EXPECT_EQ(rep.rows_skipped, 0);
  EXPECT_EQ(rep.data_lines, 3);
}

TEST(InterchangeCsvRead, RegistryPicksTheReaderByContent) {
  const auto reg = LogReaderRegistry::withBuiltinReaders();
  const LogReader* r = reg.find(fixture("good_crlf_bom.csv"));
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->formatName(), "mission-log CSV v1");
  EXPECT_EQ(reg.find(fixture("bad_random.bin")), nullptr);
  // Not interchange CSV (';' separators), but the generic text reader takes it.
  const LogReader* semi = reg.find(fixture("bad_semicolon.csv"));
  ASSERT_NE(semi, nullptr);
  EXPECT_NE(semi->formatName(), "mission-log CSV v1");
  ReadReport rep;
  EXPECT_EQ(reg.read(fixture("good_minimal.csv"), {}, rep).rowCount(), 5u);
  try {
    reg.read(fixture("bad_random.bin"), {}, rep);
    FAIL() << "random bytes were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no reader recognises"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mission-log CSV v1"), std::string::npos);
  }
  EXPECT_THROW(reg.find(fixture("does_not_exist.csv")), InputError);
}

namespace {
std::filesystem::path bigTempLog(int rows) {
  MissionLog log;
  log.setMetadata("vehicle", "test");
  LogChannel depth{"depth", "m", "m", {}};
  for (int i = 0; i < rows; ++i) {
    log.time.push_back(i * 0.1);
    depth.values.push_back(std::sin(i * 0.01) * 10.0 + 20.0);
  }
  log.channels.push_back(depth);
  const auto path = std::filesystem::temp_directory_path() /
                    ("missionlog_progress_" + std::to_string(::getpid()) + ".csv");
  writeInterchangeCsv(log, path);
  return path;
}
}  // namespace

TEST(InterchangeCsvRead, ProgressIsMonotonicAndCancelThrows) {
  const auto path = bigTempLog(20000);
  std::vector<double> seen;
  ReadOptions o;
  o.block_bytes = 4096;
  o.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  ReadReport rep;
  const MissionLog log = readInterchangeCsv(path, o, rep);
  EXPECT_EQ(log.rowCount(), 20000u);
  ASSERT_GT(seen.size(), 20u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));

  int calls = 0;
  o.progress = [&](double) { return ++calls < 3; };
  EXPECT_THROW(readInterchangeCsv(path, o, rep), ReadCancelled);
  EXPECT_EQ(calls, 3);
  std::filesystem::remove(path);
}

TEST(InterchangeCsvRead, BlockSizeDoesNotChangeTheResult) {
  const auto path = bigTempLog(3000);
  ReadReport rep;
  const MissionLog ref = readInterchangeCsv(path);
  for (std::size_t block : {64u, 100u, 4096u}) {
    ReadOptions o;
    o.block_bytes = block;
    const MissionLog log = readInterchangeCsv(path, o, rep);
    EXPECT_TRUE(rep.clean()) << block << "\n" << rep.summary();
    EXPECT_EQ(log.time, ref.time) << block;
    EXPECT_EQ(log.channels[0].values, ref.channels[0].values) << block;
  }
  std::filesystem::remove(path);
}

TEST(DecimalParse, AgreesBitForBitWithFromChars) {
  std::mt19937_64 rng(42);
  std::vector<std::string> cases = {"0", "-0", "1.", ".5", "-.5", "007", "1e5", "1E-3", "nan", "-nan",
                                    "inf", "-inf", "-", ".", "", "1.5x", "123456789012345",
                                    "1234567890123456", "0.000000000000001", "99999999999999.9",
                                    "4.35", "0.1", "-12818.116", "1e400", "1e-400", "--1", "+1"};
  for (int i = 0; i < 200000; ++i) {
    std::string s;
    if (rng() % 3 == 0) s += '-';
    const int intDigits = static_cast<int>(rng() % 9);
    for (int k = 0; k < intDigits; ++k) s += static_cast<char>('0' + rng() % 10);
    if (rng() % 4) {
      s += '.';
      const int frac = static_cast<int>(rng() % 10);
      for (int k = 0; k < frac; ++k) s += static_cast<char>('0' + rng() % 10);
    }
    cases.push_back(s);
  }
  for (const auto& s : cases) {
    const char* b = s.data();
    const char* e = b + s.size();
    double a = 0.0, ref = 0.0;
    const char* pa = parseDecimal(b, e, a);
    const auto r = std::from_chars(b, e, ref);
    if (r.ec != std::errc{}) {
      EXPECT_EQ(pa, nullptr) << s;
      continue;
    }
    ASSERT_EQ(pa, r.ptr) << s;
    if (std::isnan(ref)) {
      EXPECT_TRUE(std::isnan(a)) << s;
    } else {
      EXPECT_EQ(std::memcmp(&a, &ref, sizeof a), 0) << s << " " << a << " vs " << ref;
    }
  }
}

}  // namespace auv
