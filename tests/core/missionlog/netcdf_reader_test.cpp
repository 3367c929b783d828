// Glider NetCDF: OG1 / IOOS-DAC trajectory files and Seaglider basestation
// per-dive files, written at test time with the libnetcdf C API
// (netcdf_fixtures.h). Expected values are the numbers written plus the
// unit definitions; the interchange CSV reader is the oracle for equivalence.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>

#include "common/input_error.h"
#include "missionlog/interchange_csv.h"
#include "missionlog/log_reader.h"
#include "missionlog/netcdf_reader.h"
#include "netcdf_fixtures.h"

namespace auv {
namespace {
namespace fs = std::filesystem;
using nctest::NcWriter;

constexpr double kT0 = 1700000000.0;  // 2023-11-14T22:13:20Z
constexpr double kSg0 = 1716800716.0;  // 2024-05-27T09:05:16Z

fs::path tmp(const std::string& name) { return fs::temp_directory_path() / ("auv_nc_" + name); }
fs::path fixture(const std::string& name) { return fs::path(AUV_TEST_DATA_DIR) / "missionlog" / name; }
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
double f32(double v) { return static_cast<double>(static_cast<float>(v)); }

void expectBalanced(const ReadReport& r) {
  EXPECT_EQ(r.data_lines, r.rows_kept + r.rows_skipped + r.rows_merged) << r.summary();
}

struct Og1Options {
  int mode = NC_CLOBBER;
  std::string timeUnits = "seconds since 1970-01-01T00:00:00Z";
  std::string calendar = "gregorian";
  std::string pitchUnits = "degrees";
  std::vector<double> time = {kT0, kT0 + 10, kT0 + 20, kT0 + 30, kT0 + 40, kT0 + 50};
  std::vector<double> depth = {0.5, 5.2, -999, 15.1, 20.3, 25.0};
  bool withTime = true;
};

// An OG1-style trajectory file: N_MEASUREMENTS, TIME, DEPTH (float, fill
// -999), PRES, PITCH, ROLL, HEADING, TEMP with TEMP_QC, CNDC in mS/cm, PSAL
// in "1", and LATITUDE as an extra variable.
fs::path writeOg1(const std::string& name, const Og1Options& o = {}) {
  const fs::path p = tmp(name);
  NcWriter w(p, o.mode);
  const int n = w.dim("N_MEASUREMENTS", o.time.size());
  int time = -1;
  if (o.withTime) {
    time = w.var("TIME", NC_DOUBLE, {n});
    w.text(time, "units", o.timeUnits);
    if (!o.calendar.empty()) w.text(time, "calendar", o.calendar);
    w.text(time, "standard_name", "time");
  }
  const int depth = w.var("DEPTH", NC_FLOAT, {n});
  w.text(depth, "units", "m");
  w.number(depth, "_FillValue", NC_FLOAT, -999.0);
  const int pres = w.var("PRES", NC_DOUBLE, {n});
  w.text(pres, "units", "dbar");
  const int pitch = w.var("PITCH", NC_FLOAT, {n});
  w.text(pitch, "units", o.pitchUnits);
  const int roll = w.var("ROLL", NC_FLOAT, {n});
  w.text(roll, "units", "degrees");
  const int heading = w.var("HEADING", NC_FLOAT, {n});
  w.text(heading, "units", "degrees");
  const int temp = w.var("TEMP", NC_DOUBLE, {n});
  w.text(temp, "units", "degree_Celsius");
  const int tempQc = w.var("TEMP_QC", NC_BYTE, {n});
  const int cndc = w.var("CNDC", NC_DOUBLE, {n});
  w.text(cndc, "units", "mS/cm");
  const int psal = w.var("PSAL", NC_DOUBLE, {n});
  w.text(psal, "units", "1");
  const int lat = w.var("LATITUDE", NC_DOUBLE, {n});
  w.text(lat, "units", "degrees_north");
  w.text(NC_GLOBAL, "title", "OG1 test trajectory");
  w.text(NC_GLOBAL, "id", "sea046_20231114");
  w.number(NC_GLOBAL, "deployment_number", NC_INT, 45);
  w.endDefine();
  if (o.withTime) w.put(time, o.time);
  w.put(depth, o.depth);
  w.put(pres, {0.5, 5.25, 10.3, 15.2, 20.5, 25.2});
  w.put(pitch, {-20.0, -21.0, -22.0, -21.5, -20.5, -0.35});
  w.put(roll, {1.0, 1.25, 1.5, 1.25, 1.0, 0.75});
  w.put(heading, {90.0, 90.5, 91.0, 91.5, 92.0, 92.5});
  w.put(temp, {12.1, 12.0, 11.8, 11.5, 11.2, 11.0});
  w.put(tempQc, {1, 1, 4, 1, 1, 1});
  w.put(cndc, {35.0, 34.9, 34.8, 34.7, 34.6, 34.5});
  w.put(psal, {35.1, 35.1, 35.05, 35.0, 35.0, 34.95});
  w.put(lat, {54.1, 54.1001, 54.1002, 54.1003, 54.1004, 54.1005});
  w.close();
  return p;
}

std::string refusal(const fs::path& p) {
  ReadReport r;
  try {
    readGliderNetcdf(p, {}, r);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << p << " was accepted";
  return {};
}

TEST(GliderNetcdf, Og1TrajectoryFile) {
  const fs::path p = writeOg1("og1.nc");
  ReadReport r;
  const MissionLog log = readGliderNetcdf(p, {}, r);
  ASSERT_EQ(log.rowCount(), 6u) << r.summary();
  EXPECT_EQ(*log.metadataValue("start"), "2023-11-14T22:13:20.000Z");
  EXPECT_EQ(log.time, (std::vector<double>{0, 10, 20, 30, 40, 50}));
  EXPECT_EQ(log.channel("depth").values[1], f32(5.2));
  EXPECT_TRUE(std::isnan(log.channel("depth").values[2]));  // _FillValue
  EXPECT_EQ(log.channel("pressure").values[2], 10.3);
  EXPECT_EQ(log.channel("pitch").values[0], -20.0);
  EXPECT_EQ(log.channel("heading").unit, "deg");
  EXPECT_TRUE(std::isnan(log.channel("temperature").values[2]));  // TEMP_QC = 4
  EXPECT_EQ(log.channel("temperature").values[3], 11.5);
  EXPECT_DOUBLE_EQ(log.channel("conductivity").values[0], 3.5);  // 35 mS/cm
  EXPECT_EQ(log.channel("salinity").unit, "PSU");
  EXPECT_EQ(log.channel("salinity").values[0], 35.1);
  EXPECT_EQ(log.channel("LATITUDE").unit, "deg");
  EXPECT_FALSE(log.has("TEMP_QC"));
  EXPECT_EQ(*log.metadataValue("nc_id"), "sea046_20231114");
  EXPECT_EQ(*log.metadataValue("nc_deployment_number"), "45");
  EXPECT_EQ(log.metadataValue("missing_channels"), nullptr);
  EXPECT_EQ(r.cells_blanked, 1);  // the QC-rejected temperature
  EXPECT_EQ(r.count(ReadProblemKind::kValueOutOfRange), 1);
  expectBalanced(r);
  fs::remove(p);
}

TEST(GliderNetcdf, Netcdf4HdfFileReadsTheSame) {
  Og1Options o;
  o.mode = NC_CLOBBER | NC_NETCDF4;
  const fs::path a = writeOg1("og1_classic.nc"), b = writeOg1("og1_hdf5.nc", o);
  ReadReport ra, rb;
  const MissionLog x = readGliderNetcdf(a, {}, ra), y = readGliderNetcdf(b, {}, rb);
  EXPECT_EQ(x.time, y.time);
  ASSERT_EQ(x.channels.size(), y.channels.size());
  for (const auto& c : x.channels) {
    const auto& d = y.channel(c.name).values;
    for (std::size_t i = 0; i < c.values.size(); ++i)
      EXPECT_TRUE((std::isnan(c.values[i]) && std::isnan(d[i])) || c.values[i] == d[i]) << c.name;
  }
  fs::remove(a);
  fs::remove(b);
}

TEST(GliderNetcdf, IoosDacFileWithProfileVariables) {
  const fs::path p = tmp("ioos.nc");
  {
    NcWriter w(p);
    const int t = w.dim("time", 5), prof = w.dim("profile", 2), extra = w.dim("extra", 3);
    const int time = w.var("time", NC_DOUBLE, {t});
    w.text(time, "units", "seconds since 1970-01-01T00:00:00Z");
    const int depth = w.var("depth", NC_DOUBLE, {t});
    w.text(depth, "units", "m");
    const int pressure = w.var("pressure", NC_DOUBLE, {t});
    w.text(pressure, "units", "dbar");
    const int temp = w.var("temperature", NC_DOUBLE, {t});
    w.text(temp, "units", "Celsius");
    const int cond = w.var("conductivity", NC_DOUBLE, {t});
    w.text(cond, "units", "S m-1");
    const int sal = w.var("salinity", NC_DOUBLE, {t});
    w.text(sal, "units", "1");
    const int dens = w.var("density", NC_DOUBLE, {t});
    w.text(dens, "units", "kg m-3");
    const int ptime = w.var("profile_time", NC_DOUBLE, {prof});
    w.text(ptime, "units", "seconds since 1970-01-01T00:00:00Z");
    const int pid = w.var("profile_id", NC_INT, {prof});
    const int flag = w.var("ts_flag", NC_INT, {extra});
    w.endDefine();
    w.put(time, {kT0, kT0 + 4, kT0 + 8, kT0 + 12, kT0 + 16});
    w.put(depth, {1.0, 2.0, 3.0, 4.0, 5.0});
    w.put(pressure, {1.0, 2.0, 3.0, 4.0, 5.1});
    w.put(temp, {15.0, 14.9, 14.8, 14.7, 14.6});
    w.put(cond, {4.1, 4.1, 4.0, 4.0, 3.9});
    w.put(sal, {33.0, 33.1, 33.2, 33.3, 33.4});
    w.put(dens, {1024.1, 1024.2, 1024.3, 1024.4, 1024.5});
    w.put(ptime, {kT0 + 8, kT0 + 10});
    w.put(pid, {7, 8});
    w.put(flag, {0, 0, 0});
    w.close();
  }
  ReadReport r;
  const MissionLog log = readGliderNetcdf(p, {}, r);
  // 5 trajectory instants + 2 profile instants, one shared (t = 8 s).
  EXPECT_EQ(log.time, (std::vector<double>{0, 4, 8, 10, 12, 16}));
  EXPECT_EQ(r.rows_merged, 1);
  expectBalanced(r);
  EXPECT_EQ(log.channel("conductivity").values[0], 4.1);
  EXPECT_EQ(log.channel("conductivity").unit, "S/m");
  EXPECT_EQ(log.channel("density").unit, "kg/m3");
  EXPECT_EQ(log.channel("profile_id").values[2], 7.0);
  EXPECT_EQ(log.channel("profile_id").values[3], 8.0);
  EXPECT_TRUE(std::isnan(log.channel("depth").values[3]));  // a profile instant
  EXPECT_EQ(*log.metadataValue("missing_channels"), "pitch, roll, heading");
  EXPECT_TRUE(contains(*log.metadataValue("not_imported"), "extra (1 variables)"));
  EXPECT_TRUE(r.clean()) << r.summary();
  fs::remove(p);
}

fs::path writeSeaglider(const std::string& name) {
  const fs::path p = tmp(name);
  NcWriter w(p);
  const int sg = w.dim("sg_data_point", 5), ctd = w.dim("ctd_data_point", 4), gc = w.dim("gc_event", 2);
  const int time = w.var("time", NC_DOUBLE, {sg});
  w.text(time, "units", "seconds since 1970-1-1 00:00:00");
  auto var = [&](const char* n, int d, const char* units) {
    const int v = w.var(n, NC_DOUBLE, {d});
    w.text(v, "units", units);
    return v;
  };
  const int depth = var("depth", sg, "meters");
  const int pitch = var("eng_pitchAng", sg, "degrees");
  const int roll = var("eng_rollAng", sg, "degrees");
  const int head = var("eng_head", sg, "degrees");
  const int vbd = var("eng_vbdCC", sg, "cc");
  const int pctl = var("eng_pitchCtl", sg, "cm");
  const int rctl = var("eng_rollCtl", sg, "degrees");
  const int speed = var("speed", sg, "cm/s");
  const int ctime = var("ctd_time", ctd, "seconds since 1970-1-1 00:00:00");
  const int temp = var("temperature", ctd, "degrees_Celsius");
  const int tempQc = w.var("temperature_qc", NC_CHAR, {ctd});
  const int sal = var("salinity", ctd, "1e-3");
  const int dens = var("density_insitu", ctd, "g/m^3");
  const int gcp = var("gc_pitch_ctl", gc, "cm");
  const int mass = w.var("sg_cal_mass", NC_DOUBLE, {});
  w.number(NC_GLOBAL, "dive_number", NC_INT, 104);
  w.text(NC_GLOBAL, "platform_id", "SG171");
  w.endDefine();
  w.put(time, {kSg0, kSg0 + 5, kSg0 + 10, kSg0 + 15, kSg0 + 20});
  w.put(depth, {0.4, 1.5, 3.0, 4.6, 6.1});
  w.put(pitch, {-15.0, -17.5, -18.2, -18.0, -17.9});
  w.put(roll, {-2.0, -1.5, 0.5, 0.4, 0.3});
  w.put(head, {180.0, 181.0, 182.0, 182.5, 183.0});
  w.put(vbd, {-150.0, -150.0, -150.0, -150.0, -150.0});
  w.put(pctl, {-1.2, -1.2, -0.8, -0.8, -0.8});
  w.put(rctl, {0.0, 0.0, 40.0, 40.0, 0.0});
  w.put(speed, {12.0, 20.0, 21.5, 22.0, 22.1});
  w.put(ctime, {kSg0 + 2, kSg0 + 5, kSg0 + 8, kSg0 + 11});
  w.put(temp, {30.1, 30.0, 29.9, 29.7});
  w.putText(tempQc, "1141");
  w.put(sal, {34.1, 34.1, 34.2, 34.2});
  w.put(dens, {1021.5, 1021.6, 1021.8, 1021.9});
  w.put(gcp, {-1.2, -0.8});
  w.put(mass, {56.69});
  w.close();
  return p;
}

TEST(GliderNetcdf, SeagliderBasestationPerDiveFile) {
  const fs::path p = writeSeaglider("p1710104.nc");
  ReadReport r;
  const MissionLog log = readGliderNetcdf(p, {}, r);
  // 5 vehicle samples + 4 CTD samples, one shared (t = 5 s).
  EXPECT_EQ(log.time, (std::vector<double>{0, 2, 5, 8, 10, 11, 15, 20}));
  expectBalanced(r);
  EXPECT_EQ(*log.metadataValue("start"), "2024-05-27T09:05:16.000Z");
  EXPECT_EQ(*log.metadataValue("netcdf_flavour"), "Seaglider basestation");
  EXPECT_EQ(log.channel("pitch").values[2], -17.5);
  EXPECT_EQ(log.channel("roll").values[4], 0.5);
  EXPECT_EQ(log.channel("heading").values[0], 180.0);
  EXPECT_EQ(log.channel("pump_volume").values[0], -150.0);
  // eng_pitchCtl -1.2 cm (Seaglider: positive aft) = +12 mm forward.
  EXPECT_DOUBLE_EQ(log.channel("battery_position").values[0], 12.0);
  EXPECT_EQ(log.channel("battery_position").unit, "mm");
  EXPECT_EQ(log.channel("roll_mass").values[4], 40.0);
  EXPECT_DOUBLE_EQ(log.channel("speed_flightmodel").values[2], 0.20);  // 20 cm/s
  EXPECT_EQ(log.channel("temperature").values[1], 30.1);
  EXPECT_TRUE(std::isnan(log.channel("temperature").values[3]));  // t = 8 s: temperature_qc '4'
  EXPECT_EQ(log.channel("temperature").values[5], 29.7);
  EXPECT_EQ(log.channel("salinity").unit, "PSU");                 // "1e-3"
  EXPECT_EQ(log.channel("density").unit, "kg/m3");                // mislabelled g/m^3
  EXPECT_EQ(log.channel("density").source_unit, "g/m^3");
  EXPECT_EQ(log.channel("density").values[1], 1021.5);
  EXPECT_EQ(log.channel("dive_number").values[0], 104.0);
  EXPECT_TRUE(std::isnan(log.channel("dive_number").values[1]));  // a CTD-only instant
  EXPECT_EQ(*log.metadataValue("mass_kg"), "56.69");
  EXPECT_TRUE(contains(*log.metadataValue("not_imported"), "gc_event"));
  EXPECT_EQ(*log.metadataValue("missing_channels"), "pressure");
  fs::remove(p);
}

TEST(GliderNetcdf, DamagedTimesAreRepaired) {
  Og1Options o;
  o.time = {kT0, NC_FILL_DOUBLE, kT0 + 10, kT0 + 20, kT0 + 5, kT0 + 20};
  const fs::path p = writeOg1("og1_times.nc", o);
  ReadReport r;
  const MissionLog log = readGliderNetcdf(p, {}, r);
  EXPECT_EQ(log.time, (std::vector<double>{0, 10, 20}));
  EXPECT_EQ(r.count(ReadProblemKind::kMissingTime), 1);
  EXPECT_EQ(r.count(ReadProblemKind::kTimeNotIncreasing), 1);
  EXPECT_EQ(r.count(ReadProblemKind::kDuplicateTime), 1);
  expectBalanced(r);
  std::string all;
  for (const auto& q : r.problems) all += q.text() + "\n";
  EXPECT_TRUE(contains(all, "N_MEASUREMENTS[1]: time is empty, NaN or a fill value")) << all;
  EXPECT_TRUE(contains(all, "N_MEASUREMENTS[4]: time 2023-11-14T22:13:25.000Z breaks the increasing order")) << all;
  fs::remove(p);
}

TEST(GliderNetcdf, UnitsAreConvertedOrRefused) {
  Og1Options rad;
  rad.pitchUnits = "rad";
  const fs::path a = writeOg1("og1_rad.nc", rad);
  ReadReport r;
  const MissionLog log = readGliderNetcdf(a, {}, r);
  // PITCH in "rad" holding degrees: -20 rad is impossible, only -0.35 survives.
  EXPECT_EQ(log.channel("pitch").validCount(), 1u);
  EXPECT_DOUBLE_EQ(log.channel("pitch").values[5], f32(-0.35) * 180.0 / std::numbers::pi);
  EXPECT_GE(r.count(ReadProblemKind::kValueOutOfRange), 5);
  Og1Options metres;
  metres.pitchUnits = "m";
  const fs::path b = writeOg1("og1_m.nc", metres);
  const std::string e = refusal(b);
  EXPECT_TRUE(contains(e, "PITCH")) << e;
  EXPECT_TRUE(contains(e, "unit [m] cannot be converted to [deg]")) << e;
  fs::remove(a);
  fs::remove(b);
}

TEST(GliderNetcdf, RefusesFilesWithoutAUsableTime) {
  Og1Options none;
  none.withTime = false;
  const fs::path a = writeOg1("og1_notime.nc", none);
  const std::string ea = refusal(a);
  EXPECT_TRUE(contains(ea, "no time coordinate")) << ea;
  EXPECT_TRUE(contains(ea, "DEPTH, PRES, PITCH")) << ea;
  Og1Options bare;
  bare.timeUnits = "s";
  const fs::path b = writeOg1("og1_bare.nc", bare);
  EXPECT_TRUE(contains(refusal(b), "time-like: TIME [s]"));
  Og1Options cal;
  cal.calendar = "360_day";
  const fs::path c = writeOg1("og1_360.nc", cal);
  EXPECT_TRUE(contains(refusal(c), "calendar \"360_day\""));
  Og1Options fills;
  fills.time.assign(6, NC_FILL_DOUBLE);
  const fs::path d = writeOg1("og1_fills.nc", fills);
  EXPECT_TRUE(contains(refusal(d), "no sample has a valid time"));
  for (const auto& p : {a, b, c, d}) fs::remove(p);
}

TEST(GliderNetcdf, DamagedFilesAreRefusedNotCrashedOn) {
  const fs::path p = writeOg1("og1_full.nc");
  std::string bytes;
  {
    std::ifstream in(p, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(bytes.size(), 200u);
  // Cut at several points: every cut is refused with a message or read
  // with fewer valid values, never a crash.
  for (std::size_t cut : {std::size_t{3}, std::size_t{40}, bytes.size() / 3, bytes.size() / 2, bytes.size() - 8}) {
    ReadReport r;
    try {
      const MissionLog log = parseGliderNetcdf(bytes.data(), cut, "cut.nc", {}, r);
      EXPECT_LE(log.rowCount(), 6u);
    } catch (const InputError& e) {
      EXPECT_TRUE(contains(e.what(), "cut.nc")) << e.what();
    }
  }
  // The magic bytes of NetCDF followed by garbage.
  std::string junk = "CDF\x01";
  for (int i = 0; i < 300; ++i) junk += static_cast<char>((i * 37 + 11) & 0xff);
  ReadReport r;
  EXPECT_THROW(parseGliderNetcdf(junk.data(), junk.size(), "junk.nc", {}, r), InputError);
  EXPECT_TRUE(contains(refusal(fixture("hugin_depth.txt")), "cannot open as NetCDF"));
  EXPECT_TRUE(contains(refusal(tmp("missing.nc")), "no such file"));
  fs::remove(p);
}

TEST(GliderNetcdf, GivesTheSameLogAsTheInterchangeCsvOfTheSameData) {
  ReadReport rc;
  const MissionLog csv = readInterchangeCsv(fixture("netcdf_equivalent.csv"), {}, rc);
  ASSERT_TRUE(rc.clean()) << rc.summary();
  const double start = *csv.startEpochSeconds();
  const fs::path p = tmp("equivalent.nc");
  {
    NcWriter w(p);
    const int n = w.dim("N_MEASUREMENTS", csv.rowCount());
    const int time = w.var("TIME", NC_DOUBLE, {n});
    w.text(time, "units", "seconds since 1970-01-01T00:00:00Z");
    const std::map<std::string, std::string> og1 = {{"depth", "DEPTH"},       {"pitch", "PITCH"},
                                                    {"roll", "ROLL"},         {"heading", "HEADING"},
                                                    {"temperature", "TEMP"},  {"conductivity", "CNDC"},
                                                    {"salinity", "PSAL"},     {"pressure", "PRES"}};
    std::vector<int> ids;
    for (const auto& c : csv.channels) {
      const auto it = og1.find(c.name);
      ids.push_back(w.var(it == og1.end() ? c.name : it->second, NC_DOUBLE, {n}));
      w.text(ids.back(), "units", c.unit);
      w.number(ids.back(), "_FillValue", NC_DOUBLE, -999.0);
    }
    w.endDefine();
    std::vector<double> t;
    for (double x : csv.time) t.push_back(start + x);
    w.put(time, t);
    for (std::size_t k = 0; k < csv.channels.size(); ++k) {
      std::vector<double> v = csv.channels[k].values;
      for (double& x : v)
        if (std::isnan(x)) x = -999.0;
      w.put(ids[k], v);
    }
    w.close();
  }
  ReadReport r;
  const MissionLog nc = readGliderNetcdf(p, {}, r);
  EXPECT_TRUE(r.clean()) << r.summary();
  EXPECT_EQ(nc.time, csv.time);
  EXPECT_EQ(*nc.metadataValue("start"), *csv.metadataValue("start"));
  ASSERT_EQ(nc.channels.size(), csv.channels.size());
  for (const auto& c : csv.channels) {
    const LogChannel& d = nc.channel(c.name);
    EXPECT_EQ(d.unit, c.unit) << c.name;
    for (std::size_t i = 0; i < c.values.size(); ++i)
      EXPECT_TRUE((std::isnan(c.values[i]) && std::isnan(d.values[i])) || c.values[i] == d.values[i])
          << c.name << " row " << i;
  }
  fs::remove(p);
}

TEST(GliderNetcdf, RegistryPicksItByContentNotExtension) {
  const fs::path p = writeOg1("og1_named.dat");
  const auto reg = LogReaderRegistry::withBuiltinReaders();
  const LogReader* reader = reg.find(p);
  ASSERT_NE(reader, nullptr);
  EXPECT_EQ(reader->formatName(), GliderNetcdfReader().formatName());
  ReadReport r;
  EXPECT_EQ(reg.read(p, {}, r).rowCount(), 6u);
  fs::remove(p);
}

}  // namespace
}  // namespace auv
