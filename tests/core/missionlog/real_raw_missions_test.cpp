// Whole raw missions in shared/data/real (not part of this repository) read
// through readMission and held against the interchange CSV each folder's
// README says was made from the same files by another program (pyglider /
// python-netCDF4): for every channel the two share, every CSV sample must
// have a raw sample at the same instant (to the CSV's 1 ms grid) with the
// same value (to the CSV's written decimals). Prints, per channel, the CSV
// samples, the matched ones and the largest difference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "missionlog/interchange_csv.h"
#include "missionlog/mission_files.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

fs::path realDir() { return fs::path(AUV_SHARED_DIR) / "data" / "real"; }

struct Comparison {
  std::string channel;
  std::size_t csv_samples = 0, matched = 0;
  double max_diff = 0;
};

// Each CSV sample against the raw row at the same absolute time (+-0.5 ms).
std::vector<Comparison> compareShared(const MissionLog& csv, const MissionLog& raw) {
  const double shift = *raw.startEpochSeconds() - *csv.startEpochSeconds();
  std::vector<std::size_t> rowOf(csv.rowCount(), SIZE_MAX);
  for (std::size_t i = 0; i < csv.rowCount(); ++i) {
    const double t = csv.time[i] - shift;
    const auto it = std::lower_bound(raw.time.begin(), raw.time.end(), t - 0.0005);
    if (it != raw.time.end() && std::fabs(*it - t) <= 0.0005) rowOf[i] = static_cast<std::size_t>(it - raw.time.begin());
  }
  std::vector<Comparison> out;
  for (const auto& c : csv.channels) {
    const LogChannel* r = raw.find(c.name);
    if (!r) continue;
    Comparison k;
    k.channel = c.name;
    for (std::size_t i = 0; i < c.values.size(); ++i) {
      if (std::isnan(c.values[i])) continue;
      ++k.csv_samples;
      if (rowOf[i] == SIZE_MAX || std::isnan(r->values[rowOf[i]])) continue;
      ++k.matched;
      k.max_diff = std::max(k.max_diff, std::fabs(r->values[rowOf[i]] - c.values[i]));
    }
    out.push_back(k);
  }
  return out;
}

void print(const char* title, const MissionLog& csv, const MissionLog& raw, const ReadReport& r,
           const std::vector<Comparison>& cmp) {
  std::printf("%s: raw %zu rows, %zu channels (%s); CSV %zu rows, %zu channels; %zu shared\n", title, raw.rowCount(),
              raw.channels.size(), r.format.c_str(), csv.rowCount(), csv.channels.size(), cmp.size());
  for (const auto& k : cmp)
    std::printf("  %-26s csv %6zu  matched %6zu  max |diff| %.3g\n", k.channel.c_str(), k.csv_samples, k.matched,
                k.max_diff);
}

const Comparison* findCmp(const std::vector<Comparison>& cmp, std::string_view name) {
  for (const auto& k : cmp)
    if (k.channel == name) return &k;
  return nullptr;
}

TEST(RealRawMissions, SeaExplorerSea046RawFolderMatchesItsCsv) {
  const fs::path dir = realDir() / "seaexplorer-sea046-calvert-2020";
  if (!fs::exists(dir / "raw"))
    GTEST_SKIP() << dir << "/raw not present (shared data folder missing); skipping";
  ReadReport r, c;
  const MissionLog raw = readMission({dir / "raw"}, {}, r);
  const MissionLog csv = readInterchangeCsv(dir / "sea046-m45-yos10-14.csv", {}, c);
  const auto cmp = compareShared(csv, raw);
  print("SeaExplorer sea046 yos 10-14", csv, raw, r, cmp);
  EXPECT_TRUE(r.clean()) << r.summary();
  EXPECT_EQ(*raw.metadataValue("start"), "2020-09-08T17:45:56.000Z");  // README: 17:45:56Z
  EXPECT_EQ(*raw.metadataValue("mission_files_skipped"), "deployment.yml");
  // README: every column but the derived salinity and density comes from the raw files.
  EXPECT_EQ(cmp.size(), csv.channels.size() - 2);
  for (const auto& k : cmp) {
    EXPECT_EQ(k.matched, k.csv_samples) << k.channel;
    // The CSV writes the vehicle's own decimals; NMEA positions it rounds to 1e-6 deg.
    EXPECT_LE(k.max_diff, k.channel.rfind("gps_", 0) == 0 ? 5e-7 : 1e-9) << k.channel;
  }
  EXPECT_EQ(findCmp(cmp, "pressure")->csv_samples, 12763u);  // README: 12 763 GPCTD samples
  EXPECT_EQ(findCmp(cmp, "gps_lat")->csv_samples, 42u);      // README: 42 fixes
}

TEST(RealRawMissions, SeagliderSg171DiveFolderIsOneQuietMission) {
  const fs::path dir = realDir() / "seaglider-sg171-bay-of-bengal-2024";
  if (!fs::exists(dir / "raw"))
    GTEST_SKIP() << dir << "/raw not present (shared data folder missing); skipping";
  ReadReport r, c;
  const MissionLog raw = readMission({dir / "raw"}, {}, r);
  const MissionLog csv = readInterchangeCsv(dir / "sg171-dives100-109.csv", {}, c);
  const auto cmp = compareShared(csv, raw);
  print("Seaglider SG171 dives 100-109", csv, raw, r, cmp);
  // Normal basestation structure is no warning: one summary line.
  EXPECT_TRUE(r.clean()) << r.summary();
  EXPECT_EQ(r.summary().find('\n'), r.summary().size() - 1) << r.summary();
  EXPECT_EQ(*raw.metadataValue("mission_files_skipped"), "sg_calib_constants.m");
  const auto k = raw.seagliderConstants();
  EXPECT_EQ(k.at("sg_cal_mass"), 56.69);  // README: mass 56.690 kg
  EXPECT_NEAR(k.at("sg_cal_volmax"), 55848.6, 0.05);  // README: volmax 55 848.6 cm3
  EXPECT_TRUE(k.count("log_C_VBD")) << "log_* parameters missing";
  const auto dives = raw.series("dive_number");
  EXPECT_EQ(dives.v.front(), 100.0);
  EXPECT_EQ(dives.v.back(), 109.0);
  for (const char* name : {"depth", "pressure", "pitch", "roll", "heading", "pump_volume", "dive_number", "temperature",
                           "salinity", "conductivity", "density", "ctd_depth", "gps_lat", "gps_lon"}) {
    const Comparison* x = findCmp(cmp, name);
    ASSERT_NE(x, nullptr) << name;
    EXPECT_EQ(x->matched, x->csv_samples) << name;
  }
  // Every shared channel, to half the last decimal the CSV writes (2 for
  // pump volume, buoyancy and glide angle, 3 for depth and density, 6 for positions).
  for (const auto& x : cmp) {
    EXPECT_EQ(x.matched, x.csv_samples) << x.channel;
    const bool twoDecimals = x.channel == "pump_volume" || x.channel == "buoyancy_flightmodel" ||
                             x.channel == "glide_angle_flightmodel";
    EXPECT_LE(x.max_diff, twoDecimals ? 0.0050001 : 0.00050001) << x.channel;
  }
  EXPECT_EQ(cmp.size(), 21u);
}

}  // namespace
}  // namespace auv
