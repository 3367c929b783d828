// OG1.0 variable names (GLIDER_PITCH, GLIDER_ROLL, VBD_CC ...) and the
// Seaglider basestation structures that are no problem (GC state changes as
// two records at one instant, CTD depth and pressure on their own dimension
// under a CF standard name, eng_vbdCC without a unit, the file's own QC
// flags), on NetCDF files written here with libnetcdf.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "missionlog/netcdf_reader.h"
#include "netcdf_fixtures.h"

namespace auv {
namespace {
namespace fs = std::filesystem;
using nctest::NcWriter;

constexpr double kT0 = 1700000000.0;  // 2023-11-14T22:13:20Z
fs::path tmp(const std::string& name) { return fs::temp_directory_path() / ("auv_nc2_" + name); }

TEST(GliderNetcdfNames, Og1GliderAttitudeAndVbdAreFormatChannels) {
  const fs::path p = tmp("og1_glider.nc");
  {
    NcWriter w(p);
    const int n = w.dim("N_MEASUREMENTS", 3);
    auto var = [&](const char* name, const char* units) {
      const int v = w.var(name, NC_DOUBLE, {n});
      w.text(v, "units", units);
      return v;
    };
    const int t = var("TIME", "seconds since 1970-01-01T00:00:00Z");
    const int pres = var("PRES", "dbar");
    const int pitch = var("GLIDER_PITCH", "degrees");
    const int roll = var("GLIDER_ROLL", "rad");
    const int vbd = var("VBD_CC", "cm3");
    const int temp = var("TEMP", "degree_Celsius");
    const int cndc = var("CNDC", "mS/cm");
    const int psal = var("PSAL", "1e-3");
    w.endDefine();
    w.put(t, {kT0, kT0 + 10, kT0 + 20});
    w.put(pres, {1.0, 5.0, 9.0});
    w.put(pitch, {-20.0, -21.0, -22.0});
    w.put(roll, {0.1, 0.0, -0.1});
    w.put(vbd, {-200.0, -210.0, -220.0});
    w.put(temp, {12.0, 11.5, 11.0});
    w.put(cndc, {35.0, 35.1, 35.2});
    w.put(psal, {34.0, 34.1, 34.2});
    w.close();
  }
  ReadReport r;
  const MissionLog log = readGliderNetcdf(p, {}, r);
  EXPECT_TRUE(r.clean()) << r.summary();
  EXPECT_EQ(log.channel("pitch").values[1], -21.0);
  EXPECT_DOUBLE_EQ(log.channel("roll").values[0], 0.1 * 180.0 / M_PI);
  EXPECT_EQ(log.channel("pump_volume").values[2], -220.0);
  EXPECT_EQ(log.channel("pressure").values[2], 9.0);
  EXPECT_DOUBLE_EQ(log.channel("conductivity").values[0], 3.5);
  EXPECT_EQ(log.channel("salinity").values[1], 34.1);
  EXPECT_EQ(log.channel("temperature").values[2], 11.0);
  fs::remove(p);
}

TEST(GliderNetcdfNames, SeagliderBasestationStructureIsNoWarning) {
  const fs::path p = tmp("p1710100.nc");
  {
    NcWriter w(p);
    const int sg = w.dim("sg_data_point", 3), ctd = w.dim("ctd_data_point", 3), gcs = w.dim("gc_state", 4),
              str = w.dim("log_ID_len", 4);
    auto var = [&](const char* name, int d, const char* units) {
      const int v = w.var(name, NC_DOUBLE, {d});
      if (*units) w.text(v, "units", units);
      return v;
    };
    const int t = var("time", sg, "seconds since 1970-1-1 00:00:00");
    const int depth = var("depth", sg, "meters");
    const int vbd = var("eng_vbdCC", sg, "");  // basestation writes no unit
    const int ct = var("ctd_time", ctd, "seconds since 1970-1-1 00:00:00");
    const int cdepth = var("ctd_depth", ctd, "meters");
    w.text(cdepth, "standard_name", "depth");
    const int cpres = var("ctd_pressure", ctd, "dbar");
    w.text(cpres, "standard_name", "sea_water_pressure");
    const int temp = var("temperature", ctd, "degrees_Celsius");
    const int tqc = w.var("temperature_qc", NC_CHAR, {ctd});
    const int gst = var("gc_state_secs", gcs, "seconds since 1970-1-1 00:00:00");
    const int gstate = var("gc_state_state", gcs, "");
    const int mass = w.var("sg_cal_mass", NC_DOUBLE, {});
    const int cvbd = w.var("log_C_VBD", NC_DOUBLE, {});
    const int id = w.var("log_ID", NC_CHAR, {str});
    w.endDefine();
    w.put(t, {kT0, kT0 + 10, kT0 + 20});
    w.put(depth, {1.0, 5.0, 9.0});
    w.put(vbd, {100.0, -150.0, -150.0});
    w.put(ct, {kT0 + 1, kT0 + 11, kT0 + 21});
    w.put(cdepth, {1.1, 5.1, 9.1});
    w.put(cpres, {1.2, 5.2, 9.2});
    w.put(temp, {29.0, 28.0, 27.0});
    w.putText(tqc, "114");
    // A state change is two records at one instant: state 2 left, state 5 entered at +15 s.
    w.put(gst, {kT0 + 5, kT0 + 15, kT0 + 15, kT0 + 25});
    w.put(gstate, {1, 2, 5, 6});
    w.put(mass, {56.69});
    w.put(cvbd, {2680});
    w.putText(id, "SG17");
    w.close();
  }
  ReadReport r;
  const MissionLog log = readGliderNetcdf(p, {}, r);
  EXPECT_TRUE(r.clean()) << r.summary();
  EXPECT_EQ(r.data_lines, r.rows_kept + r.rows_skipped + r.rows_merged);
  EXPECT_EQ(log.channel("pump_volume").unit, "cm3");
  EXPECT_EQ(log.channel("pump_volume").values[0], 100.0);
  EXPECT_EQ(log.channel("ctd_depth").validCount(), 3u);     // its own name, not a second "depth"
  EXPECT_EQ(log.channel("ctd_pressure").validCount(), 3u);
  EXPECT_FALSE(log.has("depth_ctd_data_point"));
  EXPECT_EQ(log.channel("temperature").validCount(), 2u);   // QC '4' blanked quietly
  EXPECT_EQ(*log.metadataValue("qc_blanked"), "temperature 1 values flagged bad by the file's own QC");
  const auto& state = log.channel("gc_state_state");
  EXPECT_EQ(state.validCount(), 3u);
  EXPECT_EQ(log.series("gc_state_state").v, (std::vector<double>{1, 5, 6}));  // the state entered at +15 s
  const auto k = log.seagliderConstants();
  EXPECT_EQ(k.at("sg_cal_mass"), 56.69);
  EXPECT_EQ(k.at("log_C_VBD"), 2680.0);
  EXPECT_EQ(*log.metadataValue("log_ID"), "SG17");
  EXPECT_EQ(k.count("log_ID"), 0u);  // text, not a number
  fs::remove(p);
}

}  // namespace
}  // namespace auv
