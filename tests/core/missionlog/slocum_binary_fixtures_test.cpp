// The Slocum binary reader on small files made by the test writer
// (slocum_test_writer.h) and committed under tests/data/missionlog/slocum/:
// both byte orders, every value size, the state bits, LZ4 framing, caches,
// truncation and refusals. The values the files were written with are the
// oracle; conversions are checked against the formulas of the comet README
// (rad x 180/pi, in x 25.4, bar x 10, ddmm.mmmm -> deg).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "common/input_error.h"
#include "missionlog/detail/slocum_file.h"
#include "missionlog/detail/slocum_lz4.h"
#include "missionlog/log_reader.h"
#include "missionlog/slocum_binary_reader.h"
#include "slocum_test_writer.h"

namespace auv {
namespace {
namespace fs = std::filesystem;
using test::SlocumWriterCycle;
using test::SlocumWriterFile;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kT0 = 1712664000.25;

const fs::path kDir = fs::path(AUV_TEST_DATA_DIR) / "missionlog" / "slocum";

// 11 sensors (3 state bytes, the last one partly used), every value size.
SlocumWriterFile engineering(bool big) {
  SlocumWriterFile f;
  f.big_endian = big;
  f.sensors = {{"m_present_time", "timestamp", 8}, {"m_depth", "m", 4},          {"m_pitch", "rad", 4},
               {"m_battpos", "in", 4},             {"m_gps_lat", "lat", 8},      {"m_lat", "lat", 8},
               {"m_lon", "lon", 8},                {"u_test_int8", "nodim", 1},  {"u_test_int16", "nodim", 2},
               {"m_time_til_wpt", "s", 4},         {"m_roll", "rad", 4}};
  f.cycles = {
      {{2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2}, {kT0, 0.5, -0.1, 0.5, 5445.1234, 5444.8, 1506.0, -5, -1234, 93665.8, 0.05}},
      {{2, 2, 1, 0, 2, 2, 2, 2, 2, 2, 2}, {kT0 + 4, 12.25, 0, 0, 69696969, -3330.5, -12030.75, 127, 32767, kInf, kNaN}},
      {{2, 2, 2, 2, 0, 1, 1, 2, 2, 0, 2}, {kT0 + 8, 20.5, 0.4363, -0.25, 0, 0, 0, -128, -32768, 0, 0.0}},
      {{2, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0}, {kT0 + 12.5, 30.0, 0, 0, 0, 0, 0, 0, 0, 0, 0}},
  };
  return f;
}

SlocumWriterFile science(bool factored) {
  SlocumWriterFile f;
  f.big_endian = true;
  f.factored = factored;
  f.crc = "5c1e0b0e";
  f.extension = "ebd";
  f.sensors = {{"sci_m_present_time", "timestamp", 8},
               {"sci_water_temp", "degc", 4},
               {"sci_water_cond", "s/m", 4},
               {"sci_water_pressure", "bar", 4},
               {"sci_ctd41cp_timestamp", "timestamp", 8}};
  f.cycles = {{{2, 2, 2, 2, 2}, {kT0 + 1, 16.25, 1.0787, 0.05, kT0 + 0.5}},
              {{2, 2, 2, 2, 2}, {kT0 + 2, 16.5, 1.0786, 1.5, kT0 + 1.5}},
              {{2, 1, 2, 2, 0}, {kT0 + 3, 0, 1.0785, 2.75, 0}}};
  return f;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string truncated() {
  const std::string whole = test::writeSlocumBinary(engineering(false));
  return whole.substr(0, whole.size() - 6);  // inside the last cycle's depth value and without 'X'
}

struct Fixture {
  std::string name, bytes;
};

std::vector<Fixture> fixtures() {
  SlocumWriterFile noCache = engineering(false);
  noCache.factored = true;
  noCache.crc = "deadbeef";
  noCache.extension = "sbd";
  const std::string le = test::writeSlocumBinary(engineering(false));
  const std::string sci = test::writeSlocumBinary(science(true));
  return {{"unit_042-le.dbd", le},
          {"unit_042-be.dbd", test::writeSlocumBinary(engineering(true))},
          {"unit_042-le.dcd", detail::slocumLz4Compress(le)},
          {"unit_042-sci.ebd", sci},
          {"unit_042-sci.ecd", detail::slocumLz4Compress(sci)},
          {"cache/5C1E0B0E.cac", test::slocumSensorLines(science(true))},
          {"ccc/5c1e0b0e.ccc", detail::slocumLz4Compress(test::slocumSensorLines(science(true)))},
          {"unit_042-truncated.dbd", truncated()},
          {"unit_042-nocache.sbd", test::writeSlocumBinary(noCache)}};
}

// The committed files are what the writer makes (AUV_WRITE_SLOCUM_FIXTURES=1
// rewrites them), so every other test here can read them from disk as CI does.
TEST(SlocumBinaryFixtures, CommittedFilesAreTheWritersOutput) {
  const bool write = std::getenv("AUV_WRITE_SLOCUM_FIXTURES") != nullptr;
  for (const auto& f : fixtures()) {
    const fs::path p = kDir / f.name;
    if (write) {
      fs::create_directories(p.parent_path());
      std::ofstream(p, std::ios::binary) << f.bytes;
    }
    EXPECT_EQ(slurp(p), f.bytes) << p << " differs from the writer's output";
  }
}

ReadOptions options(const fs::path& cacheDir = {}) {
  ReadOptions o;
  o.slocum_cache_dir = cacheDir;
  o.slocum_user_cache = false;
  return o;
}

detail::SlocumFile decode(const std::string& name, const ReadOptions& o = options()) {
  return detail::decodeSlocumFile(slurp(kDir / name), kDir / name, o);
}

// The decoded values are exactly what the writer stored (float32 values
// rounded to float, integers as written); a "same as before" (01) cycle
// repeats the last new value, and is no sample before the first one.
void expectWrittenValues(const detail::SlocumFile& d, const SlocumWriterFile& w) {
  ASSERT_EQ(d.sensors.size(), w.sensors.size());
  ASSERT_EQ(d.cycles.cycles, w.cycles.size());
  for (std::size_t k = 0; k < w.sensors.size(); ++k) {
    EXPECT_EQ(d.sensors[k].name, w.sensors[k].name);
    EXPECT_EQ(d.sensors[k].bytes, w.sensors[k].bytes);
    std::size_t j = 0;
    std::optional<double> held;
    for (std::size_t c = 0; c < w.cycles.size(); ++c) {
      const int st = w.cycles[c].state[k];
      if (st == 2) held = w.cycles[c].value[k];
      if (st == 0 || !held) continue;
      ASSERT_LT(j, d.cycles.sensors[k].cycle.size()) << w.sensors[k].name;
      EXPECT_EQ(d.cycles.sensors[k].cycle[j], c);
      const double v = *held;
      const double want = w.sensors[k].bytes == 4 ? static_cast<double>(static_cast<float>(v)) : v;
      const double got = d.cycles.sensors[k].value[j];
      if (std::isnan(want)) EXPECT_TRUE(std::isnan(got)) << w.sensors[k].name;
      else EXPECT_EQ(got, want) << w.sensors[k].name << " cycle " << c;
      ++j;
    }
    EXPECT_EQ(j, d.cycles.sensors[k].cycle.size()) << w.sensors[k].name;
  }
}

TEST(SlocumBinaryFixtures, BothByteOrdersAndEveryValueSizeDecode) {
  const auto le = decode("unit_042-le.dbd"), be = decode("unit_042-be.dbd");
  EXPECT_TRUE(le.cycles.little_endian);
  EXPECT_FALSE(be.cycles.little_endian);
  expectWrittenValues(le, engineering(false));
  expectWrittenValues(be, engineering(true));
  EXPECT_EQ(le.cycles.time, (std::vector<double>{kT0, kT0 + 4, kT0 + 8, kT0 + 12.5}));
  EXPECT_TRUE(le.cycles.saw_end_tag);
  EXPECT_EQ(le.sensor_list_source, "the file itself");
}

TEST(SlocumBinaryFixtures, LogChannelsAreConvertedAndOnlyNewValuesAreSamples) {
  ReadReport r;
  const MissionLog log = LogReaderRegistry::withBuiltinReaders().read(kDir / "unit_042-be.dbd", options(), r);
  EXPECT_EQ(r.format, "Slocum binary");
  ASSERT_EQ(log.rowCount(), 4u);
  EXPECT_EQ(log.time, (std::vector<double>{0.0, 4.0, 8.0, 12.5}));
  EXPECT_EQ(*log.metadataValue("start"), "2024-04-09T12:00:00.250Z");
  EXPECT_EQ(*log.metadataValue("glider"), "unit_042");
  auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  const double degPerRad = 180.0 / std::numbers::pi;
  const LogChannel& depth = log.channel("depth");
  EXPECT_EQ(depth.unit, "m");
  EXPECT_EQ(depth.values, (std::vector<double>{0.5, 12.25, 20.5, 30.0}));
  // m_pitch: new in cycles 0 and 2; cycle 1 is "same as before" (01), a
  // sample of the held value; cycle 3 "not written" (00), no sample.
  const LogChannel& pitch = log.channel("pitch");
  EXPECT_EQ(pitch.unit, "deg");
  EXPECT_NEAR(pitch.values[0], f(-0.1) * degPerRad, 1e-12);
  EXPECT_EQ(pitch.values[1], pitch.values[0]);
  EXPECT_NEAR(pitch.values[2], f(0.4363) * degPerRad, 1e-12);
  EXPECT_TRUE(std::isnan(pitch.values[3]));
  const LogChannel& batt = log.channel("battery_position");
  EXPECT_EQ(batt.unit, "mm");
  EXPECT_NEAR(batt.values[0], 12.7, 1e-12);
  EXPECT_NEAR(batt.values[2], -6.35, 1e-12);
  // ddmm.mmmm -> degrees; 69696969 = no fix; the sign is the hemisphere.
  const LogChannel& gps = log.channel("m_gps_lat");
  EXPECT_EQ(gps.unit, "deg");
  EXPECT_NEAR(gps.values[0], 54.0 + 45.1234 / 60.0, 1e-12);
  EXPECT_TRUE(std::isnan(gps.values[1]));
  EXPECT_NEAR(log.channel("m_lat").values[1], -(33.0 + 30.5 / 60.0), 1e-12);
  EXPECT_EQ(log.channel("m_lat").values[2], log.channel("m_lat").values[1]);
  EXPECT_TRUE(std::isnan(log.channel("m_lat").values[3]));
  EXPECT_TRUE(std::isnan(batt.values[1]));
  EXPECT_NEAR(log.channel("m_lon").values[1], -(120.0 + 30.75 / 60.0), 1e-12);
  EXPECT_EQ(log.channel("u_test_int8").values[0], -5);
  EXPECT_EQ(log.channel("u_test_int8").values[1], 127);
  EXPECT_EQ(log.channel("u_test_int8").values[2], -128);
  EXPECT_EQ(log.channel("u_test_int16").values[1], 32767);
  EXPECT_EQ(log.channel("u_test_int16").values[2], -32768);
  // inf and nan as stored are not samples and are counted.
  EXPECT_NEAR(log.channel("m_time_til_wpt").values[0], f(93665.8), 1e-9);
  EXPECT_TRUE(std::isnan(log.channel("m_time_til_wpt").values[1]));
  EXPECT_TRUE(std::isnan(log.channel("roll").values[1]));
  EXPECT_NEAR(log.channel("roll").values[0], f(0.05) * degPerRad, 1e-12);
  EXPECT_EQ(r.count(ReadProblemKind::kValueOutOfRange), 2) << r.summary();
  EXPECT_EQ(r.cells_blanked, 2);
  EXPECT_EQ(r.data_lines, 4);
  EXPECT_EQ(r.rows_kept, 4);
}

TEST(SlocumBinaryFixtures, ScienceFileWithCacheNamedInUpperCase) {
  const auto d = decode("unit_042-sci.ebd", options(kDir / "cache"));
  EXPECT_TRUE(d.science);
  expectWrittenValues(d, science(true));
  EXPECT_EQ(fs::path(d.sensor_list_source).filename(), "5C1E0B0E.cac");
  ReadReport r;
  const MissionLog log = readSlocumBinary(kDir / "unit_042-sci.ebd", options(kDir / "cache"), r);
  EXPECT_EQ(log.rowCount(), 3u);
  EXPECT_NEAR(log.channel("pressure").values[1], 15.0, 1e-12);  // bar x 10
  EXPECT_EQ(log.channel("pressure").unit, "dbar");
  EXPECT_EQ(log.channel("temperature").values[0], 16.25);
  EXPECT_EQ(log.channel("temperature").values[2], 16.5);  // 01: the held value
  EXPECT_NEAR(log.channel("conductivity").values[2], static_cast<float>(1.0785), 1e-12);
  EXPECT_EQ(log.channel("sci_ctd41cp_timestamp").values[1], kT0 + 1.5);
}

TEST(SlocumBinaryFixtures, Lz4FilesAndCompressedCachesDecodeAsThePlainOnes) {
  const auto plain = decode("unit_042-le.dbd"), packed = decode("unit_042-le.dcd");
  EXPECT_TRUE(packed.compressed);
  expectWrittenValues(packed, engineering(false));
  const auto sci = decode("unit_042-sci.ecd", options(kDir / "ccc"));
  EXPECT_TRUE(sci.compressed);
  EXPECT_EQ(fs::path(sci.sensor_list_source).filename(), "5c1e0b0e.ccc");
  expectWrittenValues(sci, science(true));
  // The registry recognises the compressed file by content.
  const auto registry = LogReaderRegistry::withBuiltinReaders();
  EXPECT_EQ(registry.find(kDir / "unit_042-le.dcd")->formatName(), SlocumBinaryReader().formatName());
  // A block longer than what is left is refused with its offset.
  std::string bad = slurp(kDir / "unit_042-le.dcd");
  bad.resize(bad.size() - 3);
  try {
    detail::decodeSlocumFile(bad, "cut.dcd", options());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.dcd: lz4: block at byte 0 claims"), std::string::npos) << e.what();
  }
}

TEST(SlocumBinaryFixtures, TruncatedFileKeepsTheWholeCyclesAndSaysWhere) {
  ReadReport r;
  const MissionLog log = readSlocumBinary(kDir / "unit_042-truncated.dbd", options(), r);
  EXPECT_EQ(log.rowCount(), 3u);
  EXPECT_EQ(r.count(ReadProblemKind::kTruncatedLine), 1);
  ASSERT_FALSE(r.problems.empty());
  const std::string text = r.summary();
  EXPECT_NE(text.find("(after 3 data cycles): the file ends inside a data cycle"), std::string::npos) << text;
  EXPECT_NE(text.find("copy it from the glider again"), std::string::npos) << text;
}

TEST(SlocumBinaryFixtures, MissingCacheIsAClearError) {
  const fs::path empty = fs::temp_directory_path() / "auv-slocum-fixture-no-cache";
  fs::create_directories(empty);
  ReadReport r;
  try {
    readSlocumBinary(kDir / "unit_042-nocache.sbd", options(empty), r);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("unit_042-nocache.sbd:13: sensor_list_crc: the sensor list is not in the file and no cache file "
                     "for CRC deadbeef (deadbeef.cac or .ccc, any case) was found; looked in: " +
                     empty.string() + ", " + kDir.string()),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("--cache-dir DIR"), std::string::npos) << m;
  }
}

TEST(SlocumBinaryFixtures, FilesWithTheirListFillThePerUserCache) {
  const fs::path home = fs::temp_directory_path() / "auv-slocum-user-cache";
  fs::remove_all(home);
  ASSERT_EQ(::setenv("XDG_CACHE_HOME", home.c_str(), 1), 0);
  ReadOptions o = options();
  o.slocum_user_cache = true;
  ReadReport r;
  readSlocumBinary(kDir / "unit_042-le.dbd", o, r);
  const fs::path cache = home / "auvballast" / "slocum-cache" / "1a2b3c4d.cac";
  ASSERT_TRUE(fs::exists(cache));
  EXPECT_EQ(slurp(cache), test::slocumSensorLines(engineering(false)));
  // A factored file of the same list, alone in a folder, now reads.
  SlocumWriterFile w = engineering(false);
  w.factored = true;
  const fs::path lone = fs::temp_directory_path() / "auv-slocum-lone";
  fs::create_directories(lone);
  std::ofstream(lone / "x.sbd", std::ios::binary) << test::writeSlocumBinary(w);
  const auto d = detail::decodeSlocumFile(slurp(lone / "x.sbd"), lone / "x.sbd", o);
  EXPECT_EQ(d.sensor_list_source, cache.string());
  expectWrittenValues(d, w);
  ::unsetenv("XDG_CACHE_HOME");
}

// A file that continues a mission: its first cycle (every sensor's last
// value) has the time of the second; one row, the second cycle's values win.
TEST(SlocumBinaryFixtures, FirstCycleAtTheTimeOfTheSecondIsFoldedIntoIt) {
  SlocumWriterFile w = engineering(false);
  w.cycles[1].value[0] = kT0;
  ReadReport r;
  const MissionLog log = parseSlocumBinary(test::writeSlocumBinary(w), "/nonexistent/fold.dbd", options(), r);
  ASSERT_EQ(log.rowCount(), 3u);
  EXPECT_EQ(r.data_lines, 4);
  EXPECT_EQ(r.rows_merged, 1);
  EXPECT_EQ(r.rows_kept, 3);
  EXPECT_EQ(log.time, (std::vector<double>{0.0, 8.0, 12.5}));
  EXPECT_EQ(log.channel("depth").values[0], 12.25);  // cycle 1's, not cycle 0's 0.5
  EXPECT_NEAR(log.channel("battery_position").values[0], 12.7, 1e-12);  // only cycle 0 has it
  EXPECT_EQ(log.channel("u_test_int8").values[0], 127);
}

std::string refusal(const std::string& bytes, const std::string& name) {
  try {
    detail::decodeSlocumFile(bytes, name, options());
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << " accepted";
  return {};
}

TEST(SlocumBinaryFixtures, BrokenHeadersAndKnownBytesAreRefused) {
  SlocumWriterFile w = engineering(false);
  w.encoding = 4;
  const std::string enc = refusal(test::writeSlocumBinary(w), "e.dbd");
  EXPECT_NE(enc.find("e.dbd:2:14: encoding_ver: encoding_ver 4 is not"), std::string::npos) << enc;
  std::string s = test::writeSlocumBinary(engineering(false));
  const auto sa = s.find("sa\x34\x12");
  ASSERT_NE(sa, std::string::npos);
  s[sa + 4] = 'Q';  // spoil the float32 123.456
  EXPECT_NE(refusal(s, "k.dbd").find("does not hold 0x1234, 123.456 and 123456789.12345"), std::string::npos);
  EXPECT_NE(refusal(test::writeSlocumBinary(engineering(false)).substr(0, 300), "h.dbd").find("h.dbd:"),
            std::string::npos);
  EXPECT_NE(refusal("", "z.dbd").find("z.dbd: dbd_label: the file is empty (0 bytes)"), std::string::npos);
}

TEST(SlocumBinaryFixtures, TextOutputOfDbd2ascStillGoesToTheTextReader) {
  const auto registry = LogReaderRegistry::withBuiltinReaders();
  const fs::path dba = fs::path(AUV_TEST_DATA_DIR) / "missionlog" / "slocum_merged.dba";
  EXPECT_NE(registry.find(dba)->formatName(), SlocumBinaryReader().formatName());
  EXPECT_EQ(registry.find(kDir / "unit_042-le.dbd")->formatName(), SlocumBinaryReader().formatName());
}

}  // namespace
}  // namespace auv
