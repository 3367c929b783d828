// The raw comet files (../shared/data/real/slocum-comet-baltic-2016/raw, 10
// .dbd + 10 .ebd segments with their .cac caches), read one file at a time
// by the native binary reader, against comet-2016-174-05.csv, which an
// independent decoder (dbdreader) made from the same files (README there).
// Engineering channels are matched at m_present_time, CTD channels at
// sci_ctd41cp_timestamp, both to the CSV's millisecond. The CSV prints
// rounded values, so each comparison allows half a unit of the last printed
// digit of that column.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "missionlog/interchange_csv.h"
#include "missionlog/slocum_binary_reader.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

const fs::path kComet = fs::path(AUV_SHARED_DIR) / "data" / "real" / "slocum-comet-baltic-2016";

struct Shared {
  const char* csv;     // column in the CSV
  const char* ours;    // channel the reader makes
  double factor;       // ours x factor = csv (units the reader keeps as the glider wrote them)
  bool ctd;            // timed by sci_ctd41cp_timestamp
  bool complete;       // every value of ours (but each file's first cycle) is in the CSV
};

// The README's column table; gps_* are kept there only near the surface and
// water_depth without its -1 placeholder, so those are checked one way.
const Shared kShared[] = {
    {"depth", "depth", 1, false, true},
    {"pressure_nav", "m_pressure", 10, false, true},
    {"pitch", "pitch", 1, false, true},
    {"pitch_cmd", "pitch_cmd", 1, false, true},
    {"roll", "roll", 1, false, true},
    {"heading", "heading", 1, false, true},
    {"heading_cmd", "heading_cmd", 1, false, true},
    {"rudder", "rudder", 1, false, true},
    {"rudder_cmd", "rudder_cmd", 1, false, true},
    {"pump_volume", "pump_volume", 1, false, true},
    {"pump_volume_cmd", "pump_volume_cmd", 1, false, true},
    {"battery_position", "battery_position", 1, false, true},
    {"battery_position_cmd", "battery_position_cmd", 1, false, true},
    {"depth_rate", "m_depth_rate", 1, false, true},
    {"speed_glider_est", "m_speed", 1, false, true},
    {"altitude", "altitude", 1, false, true},
    {"water_depth", "m_water_depth", 1, false, false},
    {"gps_lat", "m_gps_lat", 1, false, false},
    {"gps_lon", "m_gps_lon", 1, false, false},
    {"lat_dr", "m_lat", 1, false, true},
    {"lon_dr", "m_lon", 1, false, true},
    {"current_east", "m_water_vx", 1, false, true},
    {"current_north", "m_water_vy", 1, false, true},
    {"air_pump_on", "m_air_pump", 1, false, true},
    {"vacuum", "m_vacuum", 1, false, true},
    {"battery_voltage", "m_battery", 1, false, true},
    {"current", "m_coulomb_current", 1, false, true},
    {"dive_target_depth", "c_dive_target_depth", 1, false, true},
    {"climb_target_depth", "c_climb_target_depth", 1, false, true},
    {"pressure", "pressure", 1, true, false},
    {"temperature", "temperature", 1, true, false},
    {"conductivity", "conductivity", 1, true, false},
};

long long msKey(double epoch) { return std::llround(epoch * 1000.0); }

// Decimals printed in each CSV column (the most seen), for the tolerance.
std::map<std::string, int> printedDecimals(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::vector<std::string> names;
  std::map<std::string, int> dec;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
    if (names.empty()) {
      for (auto& c : cells) names.push_back(c.substr(0, c.find(" [")));
      continue;
    }
    for (std::size_t i = 0; i < cells.size() && i < names.size(); ++i) {
      const auto dot = cells[i].find('.');
      const int d = dot == std::string::npos ? 0 : static_cast<int>(cells[i].size() - dot - 1);
      dec[names[i]] = std::max(dec[names[i]], d);
    }
  }
  return dec;
}

TEST(SlocumBinaryComet, RawFilesGiveTheValuesOfTheDecodedCsv) {
  if (!fs::exists(kComet / "raw" / "comet-2016-174-05-000.dbd"))
    GTEST_SKIP() << "comet raw files not found under " << kComet.string() << " (../shared absent)";
  ReadReport rc;
  const MissionLog csv = readInterchangeCsv(kComet / "comet-2016-174-05.csv", {}, rc);
  const double csvStart = *csv.startEpochSeconds();
  const auto decimals = printedDecimals(kComet / "comet-2016-174-05.csv");
  std::map<long long, std::size_t> csvRow;
  for (std::size_t i = 0; i < csv.rowCount(); ++i) csvRow.emplace(msKey(csvStart + csv.time[i]), i);
  auto findRow = [&](double epoch) -> const std::size_t* {
    for (long long d : {0LL, -1LL, 1LL}) {
      const auto it = csvRow.find(msKey(epoch) + d);
      if (it != csvRow.end()) return &it->second;
    }
    return nullptr;
  };

  std::map<std::string, std::size_t> compared, inCsv;
  std::map<std::string, std::set<long long>> comparedAt;
  std::size_t mismatches = 0, missing = 0, extra = 0, files = 0;
  ReadOptions o;
  o.slocum_user_cache = false;
  std::map<const char*, std::map<long long, double>> seen;  // csv column -> times we gave it
  for (const auto& e : fs::directory_iterator(kComet / "raw")) {
    const std::string ext = e.path().extension().string();
    if (ext != ".dbd" && ext != ".ebd") continue;
    ++files;
    ReadReport r;
    const MissionLog log = readSlocumBinary(e.path(), o, r);
    const double start = *log.startEpochSeconds();
    const LogChannel* ctdTime = log.find("sci_ctd41cp_timestamp");
    for (const Shared& s : kShared) {
      const LogChannel* c = log.find(s.ours);
      if (!c || (s.ctd && !ctdTime)) continue;
      const double tol = 0.5 * std::pow(10.0, -decimals.at(s.csv)) * (1 + 1e-9) + 1e-12;
      // Row 0 holds the file's first cycle, which repeats every sensor's
      // last value; the CSV leaves those cycles out, so values there that
      // the CSV does not have are expected (and CTD samples repeated from
      // the file before are compared once).
      for (std::size_t i = 0; i < log.rowCount(); ++i) {
        if (std::isnan(c->values[i])) continue;
        const double at = s.ctd ? ctdTime->values[i] : start + log.time[i];
        if (std::isnan(at)) continue;
        const double v = c->values[i] * s.factor;
        seen[s.csv][msKey(at)] = v;
        const std::size_t* row = findRow(at);
        const double want = row ? csv.channel(s.csv).values[*row] : NAN;
        if (std::isnan(want)) {
          // Not in the CSV: a value the CSV filters out (gps, water_depth, CTD).
          if (s.complete && i > 0 && ++extra <= 5)
            ADD_FAILURE() << e.path().filename() << " " << s.ours << " at " << at << " = " << v << " is not in the CSV";
          continue;
        }
        if (!comparedAt[s.csv].insert(msKey(at)).second) continue;
        ++compared[s.csv];
        double diff = v - want;
        if (std::string(s.csv).find("heading") == 0) diff = std::remainder(diff, 360.0);
        if (std::fabs(diff) > tol && ++mismatches <= 10)
          ADD_FAILURE() << e.path().filename() << " " << s.ours << " at " << at << ": " << v << " vs CSV " << want;
      }
    }
  }
  // Every CSV value of a shared channel came from some file.
  for (const Shared& s : kShared) {
    const LogChannel& c = csv.channel(s.csv);
    for (std::size_t i = 0; i < csv.rowCount(); ++i) {
      if (std::isnan(c.values[i])) continue;
      ++inCsv[s.csv];
      const long long k = msKey(csvStart + csv.time[i]);
      const auto& mine = seen[s.csv];
      if (!mine.count(k) && !mine.count(k - 1) && !mine.count(k + 1) && ++missing <= 10)
        ADD_FAILURE() << s.csv << " at CSV time " << csv.time[i] << " is in no raw file";
    }
  }
  std::size_t total = 0;
  for (const Shared& s : kShared) {
    total += compared[s.csv];
    EXPECT_EQ(compared[s.csv], inCsv[s.csv]) << s.csv << ": every CSV value compared once";
  }
  std::printf("[ comet    ] %zu files, %zu channels, %zu values compared, %zu mismatches, %zu CSV values missing\n",
              files, std::size(kShared), total, mismatches, missing);
  EXPECT_EQ(files, 20u);
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(missing, 0u);
  EXPECT_EQ(extra, 0u);
  EXPECT_GT(total, 90000u);
}

}  // namespace
}  // namespace auv
