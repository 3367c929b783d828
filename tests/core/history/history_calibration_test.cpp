// historyCalibrationMissions (core/workflow/history_calibration.h): the
// configuration's latest analysed mission read back as a calibration
// experiment, with the sensor biases its analysis had taken out; and
// addConfigurationHistory, which also takes the configuration's roll test
// and pitch sensor level check into the analysis's options.
#include <gtest/gtest.h>

#include "analysis/steady_segment_json.h"
#include "common/input_error.h"
#include "history/timestamp.h"
#include "store_fixture.h"
#include "vehicle/profile_loader.h"
#include "workflow/history_calibration.h"

namespace auv::test {
namespace {

class HistoryCalibration : public StoreTest {
 protected:
  const VehicleProfile hugin1000 = loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/hugin1000.json");
  const TimePoint t0 = parseIsoUtc("2026-05-01T08:00:00Z");

  // One analysed mission of configuration 7-1-1 whose auv_estimate holds `extra`.
  void storeAnalysis(HistoryStore& store, const nlohmann::json& extra) {
    store.addConfiguration(hugin("7-1-1", t0));
    const auto mean = [](double v) {
      analysis::MeanEstimate m;
      m.mean = v;
      m.sd = m.se = m.ci95 = 0.01;
      m.n = 100;
      return m;
    };
    analysis::SteadySegmentMeans s;
    s.speed_mps = mean(2.0);
    s.pitch_deg = mean(1.5);
    s.buoyancy_n = 8000.0;
    nlohmann::json estimate = {{"steady_segments", analysis::steadySegmentsJson({s})}};
    estimate.update(extra);
    AnalysisResult a;
    a.at = t0;
    a.result = {{"log", "first.csv"}, {"details", {{"installed_kg", {7.2, 7.2, 25.2, 25.2}}, {"auv_estimate", estimate}}}};
    store.addAnalysisResult("7-1-1", a);
  }
};

TEST_F(HistoryCalibration, TheBiasesTheAnalysisTookOutComeBackWithItsSegments) {
  HistoryStore store(db_path);
  storeAnalysis(store, {{"attitude_bias_removed_deg", {{"pitch", 0.8}, {"roll", -0.1}}}});
  const auto m = historyCalibrationMissions(store, "7-1-1", hugin1000, t0 + std::chrono::hours(1), "second.csv");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].installed_kg, (std::vector<double>{7.2, 7.2, 25.2, 25.2}));
  ASSERT_EQ(m[0].segments.size(), 1u);
  EXPECT_DOUBLE_EQ(m[0].segments[0].pitch_deg.mean, 1.5);
  EXPECT_DOUBLE_EQ(m[0].pitch_bias_removed_deg, 0.8);
  EXPECT_DOUBLE_EQ(m[0].roll_bias_removed_deg, -0.1);
  // The log being analysed is not its own history.
  EXPECT_TRUE(historyCalibrationMissions(store, "7-1-1", hugin1000, t0 + std::chrono::hours(1), "first.csv").empty());
}

TEST_F(HistoryCalibration, AnAnalysisWithoutBiasesHadNoneTakenOut) {
  HistoryStore store(db_path);
  storeAnalysis(store, nlohmann::json::object());
  const auto m = historyCalibrationMissions(store, "7-1-1", hugin1000, t0 + std::chrono::hours(1), "second.csv");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].pitch_bias_removed_deg, 0.0);
  EXPECT_EQ(m[0].roll_bias_removed_deg, 0.0);
}

TEST_F(HistoryCalibration, ADamagedBiasIsRefusedByName) {
  HistoryStore store(db_path);
  storeAnalysis(store, {{"attitude_bias_removed_deg", {{"pitch", "0.8"}, {"roll", 0.0}}}});
  try {
    historyCalibrationMissions(store, "7-1-1", hugin1000, t0 + std::chrono::hours(1), "second.csv");
    FAIL() << "a text bias was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("attitude_bias_removed_deg.pitch"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("history analysis #"), std::string::npos) << e.what();
  }
}

// The configuration's dock level check becomes the prior on the pitch
// sensor's bias, its roll test the BG; a configuration without them leaves
// the analysis's defaults (1 deg, BG free).
TEST_F(HistoryCalibration, TheConfigurationsLevelCheckAndRollTestBecomeTheAnalysissPriors) {
  HistoryStore store(db_path);
  storeAnalysis(store, nlohmann::json::object());
  analysis::AnalysisOptions plain;
  plain.log_name = "second.csv";
  addConfigurationHistory(store, "7-1-1", hugin1000, t0 + std::chrono::hours(1), plain);
  EXPECT_EQ(plain.pitch_alignment_sigma_deg, analysis::AnalysisOptions{}.pitch_alignment_sigma_deg);
  EXPECT_FALSE(plain.bg_m);
  EXPECT_EQ(plain.history.size(), 1u);

  store.setConfigurationPitchLevelCheck("7-1-1", 0.15);
  store.setConfigurationBg("7-1-1", 23.0);
  analysis::AnalysisOptions checked;
  checked.log_name = "second.csv";
  addConfigurationHistory(store, "7-1-1", hugin1000, t0 + std::chrono::hours(1), checked);
  EXPECT_DOUBLE_EQ(checked.pitch_alignment_sigma_deg, 0.15);
  ASSERT_TRUE(checked.bg_m);
  EXPECT_DOUBLE_EQ(*checked.bg_m, 0.023);
  // A BG the caller measured stays.
  analysis::AnalysisOptions given;
  given.bg_m = 0.030;
  addConfigurationHistory(store, "7-1-1", hugin1000, t0 + std::chrono::hours(1), given);
  EXPECT_DOUBLE_EQ(*given.bg_m, 0.030);
}

}  // namespace
}  // namespace auv::test
