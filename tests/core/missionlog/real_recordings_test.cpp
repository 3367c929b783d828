// The four real glider recordings in shared/data/real (not part of this
// repository). Every expected number below is taken from the README of the
// recording (row counts, spans, column counts, documented ranges and counts
// of sparse channels), not from running this reader.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "missionlog/interchange_csv.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

fs::path realDir() { return fs::path(AUV_SHARED_DIR) / "data" / "real"; }

struct Range {
  double lo, hi;
};
Range rangeOf(const MissionLog& log, std::string_view name) {
  Range r{INFINITY, -INFINITY};
  for (double v : log.channel(name).values)
    if (!std::isnan(v)) {
      r.lo = std::min(r.lo, v);
      r.hi = std::max(r.hi, v);
    }
  return r;
}

// Reads one recording; skips the test when the shared folder is not there.
#define READ_REAL_OR_SKIP(var, rel)                                                         \
  const fs::path var##_path = realDir() / (rel);                                            \
  if (!fs::exists(var##_path))                                                              \
    GTEST_SKIP() << "real recording " << var##_path << " not present (shared data folder "  \
                 << "missing); skipping";                                                   \
  ReadReport var##_report;                                                                  \
  const MissionLog var = readInterchangeCsv(var##_path, {}, var##_report);                  \
  EXPECT_TRUE(var##_report.clean()) << var##_report.summary()

}  // namespace

TEST(RealRecordings, SlocumCometBaltic2016) {
  READ_REAL_OR_SKIP(log, "slocum-comet-baltic-2016/comet-2016-174-05.csv");
  EXPECT_EQ(log.rowCount(), 19353u);            // README table
  EXPECT_EQ(log.channels.size() + 1, 36u);      // "36" columns incl. time
  EXPECT_EQ(*log.metadataValue("start"), "2016-06-23T17:51:11.771Z");
  EXPECT_DOUBLE_EQ(log.time.front(), 0.0);
  // 17:51:11 .. 21:59:07 = 4 h 07 min 56 s = 14876 s ("4.13 h").
  EXPECT_NEAR(log.duration(), 14876.0, 1.0);
  EXPECT_EQ(log.channel("pitch_cmd").validCount(), 19u);  // "only 19 values (24.6 deg)"
  EXPECT_NEAR(rangeOf(log, "pitch_cmd").lo, 24.6, 0.05);
  EXPECT_EQ(log.channel("altitude").validCount(), 55u);   // "altimeter, 55 values"
  const Range rho = rangeOf(log, "density");              // "1004.544-1007.030"
  EXPECT_NEAR(rho.lo, 1004.544, 0.0005);
  EXPECT_NEAR(rho.hi, 1007.030, 0.0005);
  const Range sal = rangeOf(log, "salinity");             // "7.3-8.6"
  EXPECT_NEAR(sal.lo, 7.3, 0.05);
  EXPECT_NEAR(sal.hi, 8.6, 0.05);
  const Range temp = rangeOf(log, "temperature");         // "5-17 degC"
  EXPECT_GT(temp.lo, 4.5);
  EXPECT_LT(temp.hi, 17.5);
  EXPECT_NEAR(rangeOf(log, "pump_volume_cmd").hi, 233.0, 1e-9);  // "+-233 commanded"
  EXPECT_NEAR(rangeOf(log, "pump_volume_cmd").lo, -233.0, 1e-9);
  EXPECT_NEAR(rangeOf(log, "depth").hi, 41.0, 1.0);          // "10 yos to 40 m"
  EXPECT_NEAR(rangeOf(log, "speed_adcp_kalman").hi, 6.7, 0.05);  // "outliers up to 6.7 m/s"
  const Range wd = rangeOf(log, "water_depth");             // "61.6-63.8 m"
  EXPECT_NEAR(wd.lo, 61.6, 0.05);
  EXPECT_NEAR(wd.hi, 63.8, 0.05);
  EXPECT_EQ(log.channel("battery_position").unit, "mm");
  EXPECT_EQ(log.channel("vacuum").unit, "inHg");  // not a table column: kept as written
}

TEST(RealRecordings, SlocumAmmoniteLigurian2008) {
  READ_REAL_OR_SKIP(log, "slocum-ammonite-ligurian-2008/ammonite-2008-028-01-000.csv");
  EXPECT_EQ(log.rowCount(), 1532u);
  EXPECT_EQ(log.channels.size() + 1, 29u);
  // 09:18:42 .. 11:05:21 = 6399 s ("1.78 h").
  EXPECT_NEAR(log.duration(), 6399.0, 1.0);
  EXPECT_NEAR(rangeOf(log, "depth").hi, 608.0, 1.0);        // "one yo to 608 m"
  EXPECT_NEAR(rangeOf(log, "pump_volume_cmd").hi, 270.0, 1e-9);
  EXPECT_NEAR(rangeOf(log, "pump_volume_cmd").lo, -270.0, 1e-9);
  const Range temp = rangeOf(log, "temperature");           // "13.1-13.8 degC"
  EXPECT_NEAR(temp.lo, 13.1, 0.05);
  EXPECT_NEAR(temp.hi, 13.8, 0.05);
  const Range rho = rangeOf(log, "density");                // "1028.5-1031.8"
  EXPECT_NEAR(rho.lo, 1028.5, 0.05);
  EXPECT_NEAR(rho.hi, 1031.8, 0.05);
  const Range tin = rangeOf(log, "internal_temperature");   // "13.5-14.8 degC"
  EXPECT_NEAR(tin.lo, 13.5, 0.05);
  EXPECT_NEAR(tin.hi, 14.8, 0.05);
  const Range pc = rangeOf(log, "pitch_cmd");               // "c_pitch = +-26 deg"
  EXPECT_NEAR(pc.hi, 26.0, 0.1);
  EXPECT_NEAR(pc.lo, -26.0, 0.1);
  // Engineering records every ~4 s with "one 25 s gap at the start".
  EXPECT_NEAR(log.time[1] - log.time[0], 25.0, 0.5);
}

TEST(RealRecordings, SeagliderSg171BayOfBengal2024) {
  READ_REAL_OR_SKIP(log, "seaglider-sg171-bay-of-bengal-2024/sg171-dives100-109.csv");
  EXPECT_EQ(log.rowCount(), 17830u);
  EXPECT_EQ(log.channels.size() + 1, 26u);
  EXPECT_EQ(*log.metadataValue("mass_kg"), "56.69");  // unknown key kept
  EXPECT_NEAR(log.duration(), 17.44 * 3600.0, 0.005 * 3600.0);  // "17.44 h"
  const Range dives = rangeOf(log, "dive_number");
  EXPECT_EQ(dives.lo, 100.0);
  EXPECT_EQ(dives.hi, 109.0);
  EXPECT_NEAR(rangeOf(log, "depth").hi, 505.0, 5.0);        // "10 dives to 505 m"
  const Range temp = rangeOf(log, "temperature");           // "30.5 degC at the surface, 9.8 at 500 m"
  EXPECT_NEAR(temp.hi, 30.5, 0.05);
  EXPECT_NEAR(temp.lo, 9.8, 0.05);
  const Range sal = rangeOf(log, "salinity");               // "32.6-35.0"
  EXPECT_NEAR(sal.lo, 32.6, 0.05);
  EXPECT_NEAR(sal.hi, 35.0, 0.05);
  const Range rho = rangeOf(log, "density");                // "1019.8-1027.0"
  EXPECT_NEAR(rho.lo, 1019.8, 0.05);
  EXPECT_NEAR(rho.hi, 1027.0, 0.05);
  // QC: "677 of 9 904 salinity/density points" blanked.
  EXPECT_EQ(log.channel("temperature").validCount(), 9904u);
  EXPECT_EQ(log.channel("salinity").validCount(), 9904u - 677u);
  EXPECT_EQ(log.channel("density").validCount(), 9904u - 677u);
  EXPECT_NEAR(rangeOf(log, "battery_position").hi, 67.0, 0.5);  // "+67 mm is the surface position"
  const Range rm = rangeOf(log, "roll_mass_cmd");           // "values 0/+-80"
  EXPECT_EQ(rm.lo, -80.0);
  EXPECT_EQ(rm.hi, 80.0);
  EXPECT_EQ(log.channel("current_east").validCount(), 10u);  // one per dive
}

TEST(RealRecordings, SeaExplorerSea046Calvert2020) {
  READ_REAL_OR_SKIP(log, "seaexplorer-sea046-calvert-2020/sea046-m45-yos10-14.csv");
  EXPECT_EQ(log.rowCount(), 13431u);
  EXPECT_EQ(log.channels.size() + 1, 25u);
  // 17:45:56 .. 21:19:35 = 12819 s ("3.56 h").
  EXPECT_NEAR(log.duration(), 12819.0, 1.0);
  EXPECT_EQ(log.channel("pressure").validCount(), 12763u);  // "12 763 samples"
  EXPECT_EQ(log.channel("gps_lat").validCount(), 42u);      // "42 fixes"
  const Range yo = rangeOf(log, "yo_number");
  EXPECT_EQ(yo.lo, 10.0);
  EXPECT_EQ(yo.hi, 14.0);
  const Range temp = rangeOf(log, "temperature");           // "6.3-15.3 degC"
  EXPECT_NEAR(temp.lo, 6.3, 0.05);
  EXPECT_NEAR(temp.hi, 15.3, 0.05);
  const Range sal = rangeOf(log, "salinity");               // "26.7-33.8"
  EXPECT_NEAR(sal.lo, 26.7, 0.05);
  EXPECT_NEAR(sal.hi, 33.8, 0.05);
  const Range rho = rangeOf(log, "density");                // "1019.9-1027.2"
  EXPECT_NEAR(rho.lo, 1019.9, 0.05);
  EXPECT_NEAR(rho.hi, 1027.2, 0.05);
  const Range pvc = rangeOf(log, "pump_volume_cmd");        // dives -250, climbs +150, surface +500
  EXPECT_EQ(pvc.lo, -250.0);
  EXPECT_EQ(pvc.hi, 500.0);
  EXPECT_NEAR(rangeOf(log, "depth").hi, 136.0, 0.5);        // "5 yos to 136 m"
  EXPECT_EQ(log.channel("internal_pressure").unit, "Pa");   // extra column, kept as written
}

TEST(RealRecordings, EveryRecordingRoundTripsThroughTheWriter) {
  const fs::path dir = realDir();
  if (!fs::exists(dir)) GTEST_SKIP() << "shared data folder " << dir << " not present; skipping";
  int n = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".csv" || entry.path().filename().string().find("constants") != std::string::npos)
      continue;
    // slocum-binary-samples/oracle/*.values.csv: per-sensor reference decodings, not logs.
    if (entry.path().parent_path().filename() == "oracle") continue;
    ++n;
    const MissionLog a = readInterchangeCsv(entry.path());
    std::stringstream text;
    writeInterchangeCsv(a, text);
    ReadReport r;
    const MissionLog b = parseInterchangeCsv(text.str(), "roundtrip", {}, r);
    EXPECT_TRUE(r.clean()) << r.summary();
    ASSERT_EQ(a.rowCount(), b.rowCount()) << entry.path();
    EXPECT_EQ(a.time, b.time) << entry.path();
    ASSERT_EQ(a.channels.size(), b.channels.size());
    for (std::size_t c = 0; c < a.channels.size(); ++c)
      for (std::size_t i = 0; i < a.rowCount(); ++i) {
        const double x = a.channels[c].values[i], y = b.channels[c].values[i];
        ASSERT_TRUE((std::isnan(x) && std::isnan(y)) || x == y) << entry.path() << " " << a.channels[c].name;
      }
  }
  EXPECT_EQ(n, 4);
}

}  // namespace auv
