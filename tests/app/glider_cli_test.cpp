// Gliders through the CLI (issue 12): analyze, model-check and plan give the
// target water and grams per bottle for the bundled Slocum example; profile
// --from makes a Seaglider profile from its own NetCDF whose analyze answer
// is a C_VBD / lead change. Oracles: the flags echoed exactly, the bottle
// grams summing to the mass to add, and the report's own hull volume carried
// to another water by V0 (1 - kappa p)(1 + alpha (T - T_ref)).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace auv {
using testing::runCli;

namespace {

const std::string kExample = std::string(AUV_RESOURCE_DIR) + "/examples/slocum_g2_model-check_compressibility.csv";

std::string tempPath(const std::string& name) { return ::testing::TempDir() + std::to_string(::getpid()) + "_" + name; }

double bottleSum(const nlohmann::json& rec) {
  double s = 0;
  for (const auto& p : rec["points"])
    if (p["name"].get<std::string>().rfind("fore", 0) == 0 || p["name"].get<std::string>().rfind("aft", 0) == 0) s += p["add_g"].get<double>();
  return s;
}

}  // namespace

TEST(GliderCli, AnalyzeGivesGramsPerBottleForTheDefaultTarget) {
  const auto r = runCli("analyze --vehicle slocum_g2 --log " + kExample);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find("piece size"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Bow bottle"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("deepest yo"), std::string::npos) << r.out;
  const auto j = runCli("analyze --vehicle slocum_g2 --log " + kExample + " --json -");
  ASSERT_EQ(j.code, 0) << j.err;
  const auto rep = nlohmann::json::parse(j.out);
  for (const char* k : {"density_kgm3", "pressure_dbar", "temperature_degC"}) EXPECT_TRUE(rep["target"][k].is_number()) << k;
  const auto& rec = rep["recommendation"];
  ASSERT_TRUE(rec.is_object()) << rep.value("recommendation_unavailable", std::string());
  EXPECT_EQ(rec["points"].size(), 6u);
  // Whole grams, rounded down so the glider never ends heavy.
  EXPECT_EQ(bottleSum(rec), std::floor(rep["mass_to_add_g"].get<double>() + 1e-9));
}

TEST(GliderCli, GivenTargetIsEchoedAndBadDepthIsRefused) {
  const auto j = runCli("analyze --vehicle slocum_g2 --log " + kExample +
                        " --target-density 1028.1 --target-pressure 420 --target-temperature 6.5 --json -");
  ASSERT_EQ(j.code, 0) << j.err;
  const auto rep = nlohmann::json::parse(j.out);
  EXPECT_EQ(rep["target"]["density_kgm3"].get<double>(), 1028.1);
  EXPECT_EQ(rep["target"]["pressure_dbar"].get<double>(), 420.0);
  EXPECT_EQ(rep["target"]["temperature_degC"].get<double>(), 6.5);
  const auto bad = runCli("analyze --vehicle slocum_g2 --log " + kExample + " --target-depth 3000");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("target-depth"), std::string::npos) << bad.err;
}

TEST(GliderCli, ModelCheckAnswersJointlyWithTheAcceptedTermsAndPlanCarriesIt) {
  const std::string report = tempPath("glider_mc.json");
  const auto r = runCli("model-check --vehicle slocum_g2 --log " + kExample + " --target-pressure 300 --target-temperature 8 --json " + report);
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j;
  std::ifstream(report) >> j;
  ASSERT_TRUE(j["mass_to_add_g"].is_number());
  ASSERT_TRUE(j["mass_to_add_sigma_g"].is_number());
  EXPECT_EQ(j["target"]["pressure_dbar"].get<double>(), 300.0);
  EXPECT_EQ(j["target"]["temperature_degC"].get<double>(), 8.0);
  const auto& g = j["model_check"]["glider_ballast"];
  ASSERT_TRUE(g.is_object());
  // The example hides a 5e-6 /dbar compressibility the profile lacks: the
  // joint answer uses it, the analysis alone does not know it.
  ASSERT_FALSE(g["terms_used"].empty());
  EXPECT_EQ(g["terms_used"][0], "hull_compressibility");
  EXPECT_EQ(j["mass_to_add_g"], g["mass_to_add_g"]);
  EXPECT_TRUE(j["model_check"]["analysis_estimate"]["mass_to_add_g"].is_number());
  // plan at another water: the report's own V0 and terms carried there.
  const auto p = runCli("plan --vehicle slocum_g2 --report " + report +
                        " --target-density 1027.5 --target-pressure 500 --target-temperature 6 --json -");
  ASSERT_EQ(p.code, 0) << p.err;
  const auto plan = nlohmann::json::parse(p.out);
  const double V = g["hull_volume_m3"].get<double>() * (1 - g["compressibility_per_dbar"].get<double>() * 500) *
                   (1 + g["thermal_expansion_per_degC"].get<double>() * (6 - g["reference_temperature_degC"].get<double>()));
  EXPECT_NEAR(plan["mass_to_add_g"].get<double>(), 1000 * (1027.5 * V - g["mass_now_kg"].get<double>()), 0.01);
  EXPECT_EQ(bottleSum(plan), std::floor(plan["mass_to_add_g"].get<double>() + 1e-9));
  std::remove(report.c_str());
}

TEST(GliderCli, SeagliderProfileFromItsOwnFileAndAVbdAnswer) {
  const std::string dir = std::string(AUV_SHARED_DIR) + "/data/real/seaglider-sg171-bay-of-bengal-2024/";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "real recordings not present: " << dir;
  const std::string out = tempPath("sg171.json");
  const auto r = runCli("profile --from " + dir + "raw/p1710100.nc --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto a = runCli("analyze --vehicle " + out + " --log " + dir + "sg171-dives100-109.csv --json -");
  ASSERT_EQ(a.code, 0) << a.err;
  const auto rep = nlohmann::json::parse(a.out);
  const auto& s = rep["recommendation"]["seaglider"];
  ASSERT_TRUE(s.is_object()) << rep["recommendation"].dump();
  // C_VBD moves by the volume the mass to add displaces at the target, 0.2453 cm3 per count.
  const double dV = -1000.0 * rep["mass_to_add_g"].get<double>() / rep["target"]["density_kgm3"].get<double>();  // cm3
  EXPECT_NEAR(s["C_VBD_new"].get<double>(), std::round(2680 + dV / -0.2453), 1.0);
  std::remove(out.c_str());
}

// model-check on the raw dive folder with the profile made from its own
// files, then plan from that report: a lead / C_VBD answer. Oracle: the same
// grams computed with basestation's flight-model constants of dive 100
// (flight-constants-per-dive.csv, written by an independent reader):
// V = (volmax + (C_VBD - VBD_MIN) VBD_CNV - vbdbias) exp(-abs_compress p + therm_expan (T - temp_ref)).
TEST(GliderCli, SeagliderModelCheckAndPlanGiveCVbdAndLeadFromTheRawDives) {
  const std::string dir = std::string(AUV_SHARED_DIR) + "/data/real/seaglider-sg171-bay-of-bengal-2024/";
  if (!std::filesystem::exists(dir + "raw")) GTEST_SKIP() << "real recordings not present: " << dir << "raw";
  const std::string prof = tempPath("sg171_mc.json"), report = tempPath("sg171_mc_report.json");
  ASSERT_EQ(runCli("profile --from " + dir + "raw/p1710100.nc --out " + prof).code, 0);
  const auto mc = runCli("model-check --vehicle " + prof + " --log " + dir + "raw --json " + report);
  ASSERT_EQ(mc.code, 0) << mc.err;
  const auto p = runCli("plan --vehicle " + prof + " --report " + report + " --json -");
  ASSERT_EQ(p.code, 0) << p.err;
  const auto plan = nlohmann::json::parse(p.out);
  const auto& s = plan["seaglider"];
  ASSERT_TRUE(s.is_object()) << plan.dump();
  const double add_g = plan["mass_to_add_g"].get<double>();
  const double rho = plan["target"]["density_kgm3"].get<double>(), pt = plan["target"]["pressure_dbar"].get<double>(),
               Tt = plan["target"]["temperature_degC"].get<double>();
  // Dive 100 in flight-constants-per-dive.csv: volmax 55848.6, C_VBD 2680,
  // VBD_MIN 500, VBD_CNV -0.2453, vbdbias 47.8019, abs_compress 8.63627e-07,
  // therm_expan 7.05e-05, temp_ref 15; sg_calib_constants.m: mass 56.690 kg.
  const double V = (55848.6 + (2680 - 500) * -0.2453 - 47.8019) * std::exp(-8.63627e-07 * pt + 7.05e-05 * (Tt - 15.0));
  const double basestation_g = 1000.0 * (rho * V * 1e-6 - 56.690);
  EXPECT_NEAR(add_g, basestation_g, 25.0) << "basestation " << basestation_g;
  // Within the VBD range no lead; C_VBD moves by the displaced volume, 0.2453 cm3 per count.
  EXPECT_EQ(s["lead_change_g"].get<double>(), 0.0);
  EXPECT_EQ(s["C_VBD_old"].get<double>(), 2680.0);
  EXPECT_NEAR(s["C_VBD_new"].get<double>(), std::round(2680 + (-add_g / rho * 1000.0) / -0.2453), 1.0);
  std::remove(prof.c_str());
  std::remove(report.c_str());
}

}  // namespace auv
