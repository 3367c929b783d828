// Black-box tests of 'auvballast plan' and 'auvballast history': exit codes,
// the JSON contract, the thesis's whole-system run (Fig. 7.9 / Table 7.2)
// through the history, and the temperature staleness rule.
#include <unistd.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.h"
#include "seawater/seawater.h"

namespace auv {
using testing::runCli;

namespace {

std::string tempPath(const std::string& name) {
  const std::string p = ::testing::TempDir() + std::to_string(::getpid()) + "_plan_cli_" + name;
  std::filesystem::remove(p);
  std::filesystem::remove(p + "-wal");
  std::filesystem::remove(p + "-shm");
  return p;
}

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// A post-mission analysis report as 'auvballast analyze' writes it.
std::string analysisReport() {
  const std::string p = tempPath("analysis.json");
  writeFile(p, R"({
    "vehicle": "hugin1000", "net_buoyancy_kg": 5.3, "net_buoyancy_sigma_kg": 0.1,
    "cg_offset_mm": {"x": 12.0, "y": 1.5}, "cg_offset_sigma_mm": {"x": 0.05, "y": 0.01},
    "errors": {"depth_m": 0.4, "pitch_deg": -3.0, "roll_deg": 4.3},
    "water": {"temperature_degC": 8.0, "salinity_psu": 35.0, "density_kgm3": 1027.7337, "pressure_dbar": 100.843, "depth_m": 100.0}
  })");
  return p;
}

// Fig. 7.9's first two records (first and post mission), in the two-line
// layout with its 6 + 5 header.
std::string figure79File() {
  const std::string p = tempPath("ballasting.txt");
  writeFile(p,
            "Config\tDate\tType\tArea\tSalinity\tTemperature\n"
            "TotalWeight\tAddedWeight\tDepthDeviation\tPitchDeviation\tRollDeviation\n"
            "sys-0-0\t19.5.2014-17:09\tHUGIN1000\tHorten\t35\t4\n"
            "1565.2\t9.6:9.6:24:24\tUnknown\tUnknown\tUnknown\n"
            "sys-0-0\t19.5.2014-20:32\tHUGIN1000\tHorten\t34.4975\t6.545581e+00\n"
            "1565.2\t9.6:9.6:24:24\t8.7594\t-0.59959\t0.73636\n");
  return p;
}

nlohmann::json parse(const testing::CliResult& r) { return nlohmann::json::parse(r.out); }

}  // namespace

TEST(PlanCli, BadInputExitsTwoNamingTheField) {
  const std::string h = " --history " + tempPath("bad.sqlite");
  struct Case {
    std::string args, field;
  };
  for (const Case& c : {Case{"plan --config 1-2-3" + h, "vehicle"},
                        Case{"plan --vehicle hugin1000" + h, "config"},
                        Case{"plan --vehicle hugin1000 --config 1/2" + h, "configuration ID"},
                        Case{"plan --vehicle hugin1000 --config 1-2-3 --policy fast --installed 0,0,0,0 --report " +
                                 analysisReport() + h,
                             "policy"},
                        Case{"plan --vehicle hugin1000 --config 1-2-3 --installed 1,2 --report " + analysisReport() + h,
                             "installed"},
                        Case{"plan --vehicle hugin1000 --config 1-2-3" + h, "config"},
                        Case{"plan --vehicle hugin1000 --config 1-2-3 --installed 0,0,0,0 --report " +
                                 analysisReport() + " --temperature warm" + h,
                             "temperature"},
                        Case{"history --config 9-9-9" + h, "config"}}) {
    const auto r = runCli(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.field), std::string::npos) << c.args << "\n" << r.err;
  }
}

TEST(PlanCli, JsonContractAndPredictionFromTheReport) {
  const std::string h = tempPath("contract.sqlite");
  const auto r = runCli("plan --vehicle hugin1000 --config 1-2-3 --report " + analysisReport() +
                        " --installed 10.8,10.8,22.8,22.8 --temperature 6 --salinity 35 --depth 50 --optional-pieces"
                        " --history " + h + " --json -");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = parse(r);
  const auto& pts = j["recommendation"]["points"];
  ASSERT_EQ(pts.size(), 4u);
  const char* names[] = {"fore_starboard", "fore_port", "aft_starboard", "aft_port"};
  double added = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(pts[i]["name"], names[i]);
    double from_pieces = 0;
    for (const auto& pc : pts[i]["pieces"]) from_pieces += pc["size_kg"].get<double>() * pc["count"].get<int>();
    EXPECT_NEAR(from_pieces, pts[i]["add_kg"].get<double>(), 1e-9);
    added += pts[i]["add_kg"].get<double>();
  }
  // Oracle: mass = rho_log V - 5.3 kg; predicted = rho_next V - mass - added
  // (HUGIN's profile hull: V = (1498 + 65) / 1024.8 m^3, no expansion).
  const double V = 1563.0 / 1024.8;
  const double mass = 1027.7337 * V - 5.3;
  const double rho_next = seawater::density(35.0, 6.0, seawater::pressureFromDepth(50.0));
  const auto& pred = j["recommendation"]["predicted"];
  EXPECT_NEAR(pred["net_buoyancy_kg"].get<double>(), rho_next * V - mass - added, 1e-5);
  for (const char* k : {"net_buoyancy_kg", "pitch_deg", "roll_deg"}) EXPECT_EQ(pred[k], j["predicted"][k]) << k;
  EXPECT_GE(pred["net_buoyancy_kg"].get<double>(), j["safety"]["margin_kg"].get<double>());
  EXPECT_LE(pred["net_buoyancy_kg"].get<double>(), 1.2);
  EXPECT_LT(std::abs(pred["pitch_deg"].get<double>()), 0.5);
  EXPECT_TRUE(j["safety"]["safe"].get<bool>());
  EXPECT_EQ(j["sources"]["water"], "operator");
  // Configuration 1-2-3 is not in that history: nothing was recorded.
  EXPECT_FALSE(j.contains("history"));
}

TEST(PlanCli, ThesisWholeSystemRunThroughTheHistory) {
  const std::string h = tempPath("thesis.sqlite");
  auto r = runCli("history --history " + h + " --import-ballasting-file " + figure79File());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Imported 2"), std::string::npos) << r.out;

  // 2014's temperature is far older than a month (thesis §5.5.3).
  r = runCli("plan --vehicle hugin1000 --config sys-0-0 --policy classic --history " + h);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("temperature"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("one month"), std::string::npos) << r.err;

  // Without a physical estimate only the classic table can plan.
  r = runCli("plan --vehicle hugin1000 --config sys-0-0 --temperature 6.545581 --salinity 34.4975 --history " + h);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("net_buoyancy_kg"), std::string::npos) << r.err;

  // Table 7.2 "Pre, mapped": 0.0, 1.2, 1.2, 2.4 kg (total 4.8 kg).
  r = runCli("plan --vehicle hugin1000 --config sys-0-0 --policy classic --temperature 6.545581 --salinity 34.4975"
             " --accept --history " + h + " --json -");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = parse(r);
  const double expected[] = {0.0, 1.2, 1.2, 2.4};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(j["recommendation"]["points"][i]["add_kg"].get<double>(), expected[i], 1e-9) << i;
  }
  EXPECT_EQ(j["policy"], "classic");
  EXPECT_TRUE(j["history"]["accepted"].get<bool>());

  // The accepted move is the new installed state: Fig. 7.9's fourth row,
  // 1570 kg with 9.6:10.8:25.2:26.4 kg.
  r = runCli("history --config sys-0-0 --history " + h + " --json -");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto hist = parse(r);
  const auto& last = hist["events"].back();
  EXPECT_EQ(last["kind"], "installed");
  const double after[] = {9.6, 10.8, 25.2, 26.4};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(last["record"]["points"][i]["mass_kg"].get<double>(), after[i], 1e-9) << i;
  }
  EXPECT_NEAR(last["record"]["total_mass_kg"].get<double>(), 1570.0, 1e-9);
  const std::string out = tempPath("exported.txt");
  r = runCli("history --config sys-0-0 --history " + h + " --export-ballasting-file " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream f(out);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("9.6:10.8:25.2:26.4"), std::string::npos) << text;
  EXPECT_NE(text.find("1570"), std::string::npos) << text;

  // The text listing shows every record, the recommendation included.
  r = runCli("history --config sys-0-0 --history " + h);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("recommendation"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("policy classic, accepted"), std::string::npos) << r.out;
}

TEST(PlanCli, InstalledAndAnalysisComeFromTheHistoryAndTheEnvironmentNamesIt) {
  const std::string h = tempPath("env.sqlite");
  ASSERT_EQ(runCli("history --history " + h + " --import-ballasting-file " + figure79File()).code, 0);
  setenv("AUVBALLAST_HISTORY", h.c_str(), 1);
  // Installed from the history (9.6:9.6:24:24), the estimate from a report.
  const auto r = runCli("plan --vehicle hugin1000 --config sys-0-0 --report " + analysisReport() +
                        " --optional-pieces --json -");
  unsetenv("AUVBALLAST_HISTORY");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = parse(r);
  EXPECT_EQ(j["sources"]["installed"], "history");
  EXPECT_EQ(j["sources"]["water"], "last mission");  // the report's own water, fresh
  EXPECT_EQ(j["history"]["file"], h);
  for (std::size_t i = 0; i < 4; ++i) {
    const double installed[] = {9.6, 9.6, 24.0, 24.0};
    EXPECT_GE(installed[i] + j["recommendation"]["points"][i]["add_kg"].get<double>(), -1e-9) << i;
  }
}
TEST(PlanCli, ModelCheckAcceptIntoAnUnknownConfigurationIsRefused) {
  // --config saves the accepted terms as that configuration's model; a
  // configuration the history does not have is named, and nothing is saved.
  const std::string h = tempPath("model.sqlite"), profile = tempPath("slocum.model-check.json");
  const auto r = runCli("model-check --vehicle slocum_g2 --log " + std::string(AUV_RESOURCE_DIR) +
                        "/examples/slocum_g2_model-check_compressibility.csv --accept --config 4-4-4 --history " + h +
                        " --out-profile " + profile);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("config"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("4-4-4"), std::string::npos) << r.err;
}

}  // namespace auv

namespace auv {
// issue 15: the CLI can create a configuration (first-mission --config
// --history), plan then starts from what it recorded, and --accept for a
// configuration the history does not hold is refused with that command.
TEST(PlanCli, FirstMissionCreatesTheConfigurationThatPlanAccepts) {
  const std::string h = tempPath("first_mission.sqlite");
  const std::string weighing = std::string(AUV_RESOURCE_DIR) + "/examples/hugin1000_first_mission.json";
  auto r = runCli("plan --vehicle hugin1000 --config 4-5-6 --report " + analysisReport() +
                  " --installed 14.4,14.4,19.2,19.2 --temperature 8 --salinity 35 --depth 50 --accept --history " + h);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.err.find("'4-5-6' is not in the history"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("first-mission --weighing FILE.json --config 4-5-6 --history " + h), std::string::npos) << r.err;

  r = runCli("first-mission --weighing " + weighing + " --config 4-5-6 --history " + h + " --json -");
  ASSERT_EQ(r.code, 0) << r.err;
  const double weight_kg = parse(r)["weight_kg"].get<double>();
  r = runCli("first-mission --weighing " + weighing + " --config 4-5-6 --history " + h);
  EXPECT_EQ(r.code, 2);  // an existing ID is never overwritten
  EXPECT_NE(r.err.find("already exists"), std::string::npos) << r.err;

  // Installed pieces and the vehicle's mass now come from the history.
  r = runCli("plan --vehicle hugin1000 --config 4-5-6 --report " + analysisReport() +
             " --temperature 8 --salinity 35 --depth 50 --accept --json - --history " + h);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(parse(r)["sources"]["installed"], "history");
  r = runCli("history --config 4-5-6 --json - --history " + h);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string listing = r.out;
  EXPECT_NE(listing.find("14.4"), std::string::npos);  // the weighed state (the crane file's installed_kg)
  char total[32];
  std::snprintf(total, sizeof total, "%.1f", weight_kg);
  EXPECT_NE(listing.find(std::string(total).substr(0, 4)), std::string::npos) << listing.substr(0, 2000);
}

TEST(PlanCli, ReportOfAnotherVehicleIsRefused) {
  const std::string p = tempPath("glider_report.json");
  writeFile(p, R"({"vehicle": "slocum_g2", "vehicle_kind": "glider", "net_buoyancy_kg": 0.1,
    "net_buoyancy_sigma_kg": 0.01, "water": {"temperature_degC": 8.0, "salinity_psu": 35.0, "depth_m": 50.0}})");
  const auto r = runCli("plan --vehicle hugin1000 --config 1-2-3 --report " + p +
                        " --installed 0,0,0,0 --no-save --temperature 8 --salinity 35");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.err.find(p), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("analyses vehicle 'slocum_g2', not 'hugin1000'"), std::string::npos) << r.err;
}

// The analysis writes cruise.trimmed (the trimmed vehicle's cruise speed and
// torque change) when the log fitted the propeller torque: plan reads it, and
// a misspelt key inside it is refused by its JSON path like any other.
TEST(PlanCli, CruiseTrimmedIsReadAndAMisspeltKeyInsideIsRefused) {
  auto report = [](const std::string& name, const std::string& trimmed_key) {
    const std::string p = tempPath(name);
    writeFile(p, R"({"vehicle": "hugin1000", "net_buoyancy_kg": 5.3, "net_buoyancy_sigma_kg": 0.1,
      "cg_offset_mm": {"x": 12.0, "y": 1.5}, "cg_offset_sigma_mm": {"x": 0.05, "y": 0.01},
      "cruise": {"prop_rpm": 160, "speed_mps": 1.9, "roll_deg": 4.0, "roll_sigma_deg": 0.05, "cg_y_mm": 1.4,
                 "cg_y_sigma_mm": 0.02, "trimmed": {")" + trimmed_key + R"(": 2.0, "torque_change_nm": -3.2, "cg_y_shift_mm": -0.2}},
      "water": {"temperature_degC": 8.0, "salinity_psu": 35.0, "depth_m": 100.0}})");
    return p;
  };
  const std::string args = " --installed 10.8,10.8,22.8,22.8 --no-save --temperature 8 --salinity 35 --json -";
  const auto ok = runCli("plan --vehicle hugin1000 --config 1-2-3 --report " + report("trimmed.json", "speed_mps") + args);
  ASSERT_EQ(ok.code, 0) << ok.err;
  const auto bad = runCli("plan --vehicle hugin1000 --config 1-2-3 --report " + report("typo.json", "speed_mp") + args);
  EXPECT_EQ(bad.code, 2) << bad.out;
  EXPECT_NE(bad.err.find("speed_mp"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("trimmed"), std::string::npos) << bad.err;
}
}  // namespace auv
