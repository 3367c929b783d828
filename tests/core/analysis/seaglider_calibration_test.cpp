// A Seaglider profile from its own per-dive NetCDF, read through the
// mission-log reader (the constants are the log's metadata,
// MissionLog::seagliderConstants()): the values must be the file's
// sg_cal_* / log_* scalars (as listed in the dataset's
// flight-constants-per-dive.csv, written by an independent reader), and the
// hull volume basestation's volmax + (C_VBD - VBD_MIN) VBD_CNV - vbdbias.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "analysis/profile_constants.h"
#include "common/input_error.h"
#include "missionlog/log_reader.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"
#include "vehicle/seaglider_calibration.h"

using namespace auv;

TEST(SeagliderCalibration, ReadsTheConstantsOfDive100AndMakesALoadableProfile) {
  const std::string nc = std::string(AUV_SHARED_DIR) + "/data/real/seaglider-sg171-bay-of-bengal-2024/raw/p1710100.nc";
  if (!std::filesystem::exists(nc)) GTEST_SKIP() << "real recordings not present: " << nc;
  ReadReport rr;
  const MissionLog log = LogReaderRegistry::withBuiltinReaders().read(nc, ReadOptions{}, rr);
  const SeagliderCalibration c = analysis::seagliderCalibrationOf(log, nc);
  EXPECT_DOUBLE_EQ(c.get("sg_cal_mass"), 56.69);
  EXPECT_NEAR(c.get("sg_cal_volmax"), 55848.6, 0.05);  // the CSV lists it to 0.1 cm3
  EXPECT_NEAR(c.get("sg_cal_vbdbias"), 47.8019, 1e-4);
  EXPECT_NEAR(c.get("sg_cal_hd_a"), 0.000707946, 1e-9);
  EXPECT_NEAR(c.get("sg_cal_abs_compress"), 8.63627e-07, 1e-12);
  EXPECT_EQ(c.get("log_C_VBD"), 2680.0);
  EXPECT_NEAR(c.get("log_VBD_CNV"), -0.2453, 1e-7);
  const nlohmann::json tpl = JsonReader::parseFile(std::string(AUV_RESOURCE_DIR) + "/vehicles/seaglider.json");
  const nlohmann::json p = seagliderProfile(c, tpl);
  const std::string out = ::testing::TempDir() + "sg171_profile_test.json";
  std::ofstream(out) << p.dump(2);
  const VehicleProfile v = loadVehicleProfile(out);
  EXPECT_EQ(v.id, "sg171");
  EXPECT_DOUBLE_EQ(v.mass_kg, 56.69);
  // 55848.6 + (2680 - 500) (-0.2453) - 47.8019 = 55266.0441 cm3.
  EXPECT_NEAR(v.hull.volume_m3 * 1e6, 55266.0441, 0.05);
  EXPECT_EQ(v.hull.reference_temperature_degC, 15.0);
  EXPECT_NEAR(v.hull.thermal_expansion_per_degC, 7.05e-5, 1e-12);
  EXPECT_EQ(v.sections["flight_model"]["form"], "seaglider");
  EXPECT_EQ(v.sections["seaglider"]["C_PITCH"].get<double>(), 2145.0);
  std::remove(out.c_str());
}

TEST(SeagliderCalibration, RefusesALogWithoutSeagliderConstants) {
  MissionLog log;
  log.time = {0.0, 1.0, 2.0};
  log.addChannel("depth", "m").values = {1.0, 2.0, 3.0};
  log.setMetadata("sg_cal_mass", "52.1");  // no sg_cal_volmax
  try {
    analysis::seagliderCalibrationOf(log, "slocum.csv");
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "from");
    EXPECT_NE(std::string(e.what()).find("sg_cal_volmax"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("slocum.csv"), std::string::npos) << e.what();
  }
}
