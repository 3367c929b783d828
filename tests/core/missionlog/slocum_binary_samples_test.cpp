// The native Slocum binary reader against independent decodings of real
// files (../shared/data/real/slocum-binary-samples, see its README): every
// value of every sensor of each file as dbdreader 0.6.3 decoded it
// (oracle/<file>.values.csv), and the vendor's own dbd2asc output for one
// sensor. Skips with a message when ../shared is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "common/input_error.h"
#include "missionlog/detail/slocum_cache.h"
#include "missionlog/detail/slocum_file.h"
#include "missionlog/log_reader.h"
#include "missionlog/slocum_binary_reader.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

const fs::path kSamples = fs::path(AUV_SHARED_DIR) / "data" / "real" / "slocum-binary-samples";

#define SKIP_WITHOUT_SAMPLES()                                                                        \
  if (!fs::exists(kSamples / "README.md"))                                                            \
    GTEST_SKIP() << "real Slocum samples not found at " << kSamples.string() << " (../shared absent)"

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool sameBits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

struct OracleRow {
  double t, v;
};
struct OracleSensor {
  std::string unit;
  std::vector<OracleRow> rows;
};

// oracle/<file>.values.csv: `sensor,unit,time_s,value`, 17 significant
// digits (or Python's shortest repr), "inf"/"nan" as stored.
std::map<std::string, OracleSensor> readOracle(const fs::path& p) {
  std::map<std::string, OracleSensor> out;
  std::ifstream in(p);
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      EXPECT_EQ(line, "sensor,unit,time_s,value");
      continue;
    }
    const auto a = line.find(','), b = line.find(',', a + 1), c = line.find(',', b + 1);
    auto& s = out[line.substr(0, a)];
    s.unit = line.substr(a + 1, b - a - 1);
    s.rows.push_back({std::strtod(line.c_str() + b + 1, nullptr), std::strtod(line.c_str() + c + 1, nullptr)});
  }
  return out;
}

ReadOptions sampleOptions(const fs::path& cacheDir = kSamples / "cac") {
  ReadOptions o;
  o.slocum_cache_dir = cacheDir;
  o.slocum_user_cache = false;
  return o;
}

detail::SlocumFile decode(const std::string& name, const ReadOptions& o = sampleOptions()) {
  return detail::decodeSlocumFile(slurp(kSamples / name), kSamples / name, o);
}

struct Tally {
  std::size_t sensors = 0, values = 0, mismatches = 0;
};

// Every sensor's new values with the time of their cycle, compared with the
// oracle bit for bit; every oracle sensor must be in the file.
Tally compareWithOracle(const std::string& name) {
  Tally t;
  const detail::SlocumFile f = decode(name);
  auto oracle = readOracle(kSamples / "oracle" / (name + ".values.csv"));
  EXPECT_FALSE(oracle.empty()) << name;
  EXPECT_TRUE(f.cycles.damage.empty()) << name << ": " << f.cycles.damage;
  EXPECT_TRUE(f.cycles.ended_cleanly) << name << ": stopped at byte " << f.cycles.damage_at << " after "
                                      << f.cycles.cycles << " cycles: " << f.cycles.damage;
  std::size_t withValues = 0;
  for (std::size_t k = 0; k < f.sensors.size(); ++k) {
    const auto& s = f.sensors[k];
    const auto& sv = f.cycles.sensors[k];
    if (sv.cycle.empty()) continue;
    ++withValues;
    const auto it = oracle.find(s.name);
    if (it == oracle.end()) {
      ADD_FAILURE() << name << ": " << s.name << " has values but is not in the oracle";
      ++t.mismatches;
      continue;
    }
    ++t.sensors;
    EXPECT_EQ(it->second.unit, s.unit) << name << " " << s.name;
    const auto& rows = it->second.rows;
    if (rows.size() != sv.cycle.size()) {
      ADD_FAILURE() << name << ": " << s.name << " has " << sv.cycle.size() << " values, the oracle " << rows.size();
      ++t.mismatches;
      continue;
    }
    for (std::size_t j = 0; j < rows.size(); ++j) {
      ++t.values;
      const double time = f.cycles.time[sv.cycle[j]];
      if (!sameBits(time, rows[j].t) || !sameBits(sv.value[j], rows[j].v)) {
        if (++t.mismatches <= 5)
          ADD_FAILURE() << name << ": " << s.name << " value " << j << ": (" << time << ", " << sv.value[j]
                        << ") vs oracle (" << rows[j].t << ", " << rows[j].v << ")";
      }
    }
  }
  EXPECT_EQ(withValues, oracle.size()) << name << ": sensors with values vs oracle sensors";
  return t;
}

const char* const kFiles[] = {"01600000.ecd",
                              "01600001.dbd",
                              "01600001.dcd",
                              "01600001.ebd",
                              "01600001.ecd",
                              "02450133.tcd",
                              "amadeus-2014-204-05-000.dbd",
                              "amadeus-2014-204-05-000.ebd",
                              "amadeus-2014-204-05-000.sbd",
                              "amadeus-2014-204-05-000.tbd",
                              "ammonite-2008-028-01-000.mbd",
                              "electa-2023-143-00-050.sbd",
                              "electa-2023-143-00-050.tbd"};

TEST(SlocumBinarySamples, EveryFileDecodesToTheOracleValuesBitForBit) {
  SKIP_WITHOUT_SAMPLES();
  Tally total;
  std::size_t files = 0;
  for (const char* name : kFiles) {
    const Tally t = compareWithOracle(name);
    std::printf("[ oracle   ] %-30s %5zu sensors %8zu values %zu mismatches\n", name, t.sensors, t.values,
                t.mismatches);
    total.sensors += t.sensors;
    total.values += t.values;
    total.mismatches += t.mismatches;
    ++files;
  }
  std::printf("[ oracle   ] total: %zu files, %zu sensors, %zu values, %zu mismatches\n", files, total.sensors,
              total.values, total.mismatches);
  // Every oracle file is covered by the list above.
  std::size_t oracleFiles = 0;
  for (const auto& e : fs::directory_iterator(kSamples / "oracle")) oracleFiles += e.path().extension() == ".csv";
  EXPECT_EQ(files, oracleFiles);
  EXPECT_EQ(total.mismatches, 0u);
  EXPECT_GT(total.values, 480000u);
}

void expectSameDecoding(const detail::SlocumFile& a, const detail::SlocumFile& b) {
  ASSERT_EQ(a.sensors.size(), b.sensors.size());
  ASSERT_EQ(a.cycles.cycles, b.cycles.cycles);
  for (std::size_t i = 0; i < a.cycles.cycles; ++i) ASSERT_TRUE(sameBits(a.cycles.time[i], b.cycles.time[i]));
  for (std::size_t k = 0; k < a.sensors.size(); ++k) {
    EXPECT_EQ(a.sensors[k].name, b.sensors[k].name);
    ASSERT_EQ(a.cycles.sensors[k].cycle, b.cycles.sensors[k].cycle) << a.sensors[k].name;
    for (std::size_t j = 0; j < a.cycles.sensors[k].value.size(); ++j)
      ASSERT_TRUE(sameBits(a.cycles.sensors[k].value[j], b.cycles.sensors[k].value[j])) << a.sensors[k].name;
  }
}

TEST(SlocumBinarySamples, PlainAndCompressedVersionsAreIdentical) {
  SKIP_WITHOUT_SAMPLES();
  for (const char* stem : {"01600001.dbd", "01600001.ebd"}) {
    std::string packed = stem;
    packed[packed.size() - 2] = 'c';
    const auto plain = decode(stem), lz4 = decode(packed);
    EXPECT_FALSE(plain.compressed);
    EXPECT_TRUE(lz4.compressed);
    EXPECT_GT(plain.cycles.cycles, 100u);
    expectSameDecoding(plain, lz4);
    // Through the registry too: the same log.
    ReadReport r1, r2;
    const auto registry = LogReaderRegistry::withBuiltinReaders();
    const MissionLog l1 = registry.read(kSamples / stem, sampleOptions(), r1);
    const MissionLog l2 = registry.read(kSamples / packed, sampleOptions(), r2);
    EXPECT_EQ(r1.format, "Slocum binary");
    ASSERT_EQ(l1.rowCount(), l2.rowCount());
    ASSERT_EQ(l1.channels.size(), l2.channels.size());
    for (std::size_t c = 0; c < l1.channels.size(); ++c)
      for (std::size_t i = 0; i < l1.rowCount(); ++i)
        ASSERT_TRUE(sameBits(l1.channels[c].values[i], l2.channels[c].values[i])) << l1.channels[c].name;
  }
}

TEST(SlocumBinarySamples, CompressedCachesAloneAreEnough) {
  SKIP_WITHOUT_SAMPLES();
  for (const char* name : {"01600001.dbd", "01600001.dcd", "01600001.ebd", "01600001.ecd"}) {
    const auto viaCcc = decode(name, sampleOptions(kSamples / "ccc-only"));
    EXPECT_NE(viaCcc.sensor_list_source.find(".ccc"), std::string::npos) << viaCcc.sensor_list_source;
    expectSameDecoding(decode(name), viaCcc);
  }
}

TEST(SlocumBinarySamples, UpperCaseCacheNameOfThe2008MbdIsFound) {
  SKIP_WITHOUT_SAMPLES();
  const auto f = decode("ammonite-2008-028-01-000.mbd");
  EXPECT_EQ(f.header.sensor_list_crc, "813B137D");
  EXPECT_EQ(f.sensor_list_source, "the file itself");
  // The cache folder holds it in lower case; the lookup ignores case and the
  // list in the cache is the list in the file.
  const auto found = detail::findSlocumCache({kSamples / "cac"}, "813B137D");
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->filename(), "813b137d.cac");
  const auto cached = detail::parseSlocumCache(detail::loadSlocumCache(*found), f.header.sensors_per_cycle, "c");
  ASSERT_EQ(cached.sensors.size(), f.sensors.size());
  for (std::size_t k = 0; k < f.sensors.size(); ++k) EXPECT_EQ(cached.sensors[k].name, f.sensors[k].name);
}

std::string refusal(const fs::path& p, const ReadOptions& o = sampleOptions()) {
  ReadReport r;
  try {
    LogReaderRegistry::withBuiltinReaders().read(p, o, r);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << p << " was accepted";
  return {};
}

TEST(SlocumBinarySamples, EmptyAndInvalidEncodingFilesAreRefusedClearly) {
  SKIP_WITHOUT_SAMPLES();
  const std::string empty = refusal(kSamples / "empty-2014-204-05-000.dbd");
  EXPECT_NE(empty.find("empty-2014-204-05-000.dbd"), std::string::npos) << empty;
  EXPECT_NE(empty.find("the file is empty (0 bytes)"), std::string::npos) << empty;
  EXPECT_NE(empty.find("copy the file from the glider again"), std::string::npos) << empty;
  const std::string bad = refusal(kSamples / "invalid_encoding-2014-204-05-000.dbd");
  EXPECT_NE(bad.find("invalid_encoding-2014-204-05-000.dbd:2:"), std::string::npos) << bad;
  EXPECT_NE(bad.find("encoding_ver 6 is not the Slocum binary encoding this reader knows (5)"), std::string::npos)
      << bad;
  EXPECT_NE(bad.find("dbd2asc"), std::string::npos) << bad;
}

TEST(SlocumBinarySamples, MissingCacheNamesTheCrcAndEveryPlaceLooked) {
  SKIP_WITHOUT_SAMPLES();
  const fs::path nowhere = fs::temp_directory_path() / "auv-slocum-no-cache";
  fs::create_directories(nowhere);
  const std::string e = refusal(kSamples / "01600001.dbd", sampleOptions(nowhere));
  EXPECT_NE(e.find("01600001.dbd"), std::string::npos) << e;
  EXPECT_NE(e.find("CRC 06a36d4e"), std::string::npos) << e;
  EXPECT_NE(e.find("looked in: " + nowhere.string() + ", " + kSamples.string() + ";"), std::string::npos) << e;
  EXPECT_NE(e.find("--cache-dir DIR"), std::string::npos) << e;
}

// dbd2asc_output.txt: the vendor tool's rows of m_time_til_wpt in
// amadeus-2014-204-05-000.dbd, "time value" with NaN = not written; dbd2asc
// prints about 15 significant digits of the time and 6 of the value. Its
// excerpt starts at the file's second data cycle (the time of its first row
// is that cycle's m_present_time), and it prints a value for cycles marked
// "same as before" (01) too, which is why the reader counts those as samples.
TEST(SlocumBinarySamples, AmadeusMatchesTheVendorsDbd2ascOutput) {
  SKIP_WITHOUT_SAMPLES();
  const auto f = decode("amadeus-2014-204-05-000.dbd");
  std::size_t k = 0;
  while (k < f.sensors.size() && f.sensors[k].name != "m_time_til_wpt") ++k;
  ASSERT_LT(k, f.sensors.size());
  std::map<std::uint32_t, double> written;
  for (std::size_t j = 0; j < f.cycles.sensors[k].cycle.size(); ++j)
    written[f.cycles.sensors[k].cycle[j]] = f.cycles.sensors[k].value[j];
  std::ifstream in(kSamples / "dbd2asc_output.txt");
  std::string line;
  std::uint32_t cycle = 1;
  int rows = 0, infs = 0, nans = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string ts, vs;
    s >> ts >> vs;
    const double t = std::strtod(ts.c_str(), nullptr);
    ASSERT_LT(cycle, f.cycles.cycles);
    EXPECT_NEAR(f.cycles.time[cycle], t, 1e-4) << "row " << rows;
    const auto it = written.find(cycle);
    if (vs == "NaN") {
      EXPECT_EQ(it, written.end()) << "row " << rows << " is not written in dbd2asc";
      ++nans;
    } else {
      ASSERT_NE(it, written.end()) << "row " << rows;
      const double v = std::strtod(vs.c_str(), nullptr);
      if (std::isinf(v)) {
        EXPECT_TRUE(std::isinf(it->second) && it->second > 0) << "row " << rows;
        ++infs;
      } else {
        EXPECT_NEAR(it->second, v, 5e-6 * std::max(1.0, std::fabs(v))) << "row " << rows;
      }
    }
    ++cycle;
    ++rows;
  }
  EXPECT_EQ(rows, 24);
  EXPECT_EQ(infs, 3);
  EXPECT_EQ(nans, 8);
  // The log keeps the finite values and counts the inf ones.
  ReadReport r;
  const MissionLog log = readSlocumBinary(kSamples / "amadeus-2014-204-05-000.dbd", sampleOptions(), r);
  EXPECT_GE(r.count(ReadProblemKind::kValueOutOfRange), 3) << r.summary();
  EXPECT_EQ(log.rowCount(), f.cycles.cycles);
  const LogChannel& c = log.channel("m_time_til_wpt");
  EXPECT_EQ(c.values[1], 0.0);
  EXPECT_TRUE(std::isnan(c.values[2]));
  EXPECT_NEAR(c.values[10], 93665.8, 0.05);
  EXPECT_TRUE(std::isnan(c.values[13]));  // inf in the file: not a sample in the log
}

}  // namespace
}  // namespace auv
