// What the log import page adds to the AUV analysis besides the log: the
// configuration's history (its second mission calibrates with the first,
// issue 11 item 3, as `model-check --config` does) and the pitch sensor's
// level check (the prior on the sensor's bias). Oracles: the same analysis
// run here through core, and the simulator's truth in the log header.
#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QLabel>
#include <QRadioButton>
#include <QTableWidget>
#include <QTest>
#include <cmath>

#include "analysis/calibration_parameter.h"
#include "analysis/mission_analysis.h"
#include "common/input_error.h"
#include "history/store.h"
#include "missionlog/interchange_csv.h"
#include "pages/deviation_plots_page.h"
#include "pages/log_import_page.h"
#include "sim/mission_plan.h"
#include "sim/sim_log.h"
#include "sim/simulator.h"
#include "typing.h"
#include "ui_fixture.h"
#include "vehicle/vehicle_catalog.h"
#include "widgets/number_input.h"
#include "wizard/demo_state.h"
#include "wizard/history_save.h"
#include "wizard/operator_wizard.h"
#include "wizard/session_json.h"
#include "workflow/history_calibration.h"

namespace auv::ui {
using auv::testing::find;

namespace {

const std::string kExamples = std::string(AUV_RESOURCE_DIR) + "/examples/";
const char* kInstalledFields[4] = {"installed_fore_starboard", "installed_fore_port", "installed_aft_starboard",
                                   "installed_aft_port"};

// The bundled ballast-error mission (3 kg light, 5 mm nose heavy, truth in
// the header) flown with `installed` kg at the four points.
void simulateMission(const std::vector<double>& installed, std::uint64_t seed, const std::string& out) {
  const std::string plan_file = kExamples + "hugin1000_ballast_error.plan.json";
  sim::MissionPlan plan = sim::loadMissionPlan(plan_file);
  plan.installed_kg = installed;
  plan.options.seed = seed;
  const VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load(plan.vehicle);
  const sim::SimVehicle sv = sim::loadSimVehicle(v, AUV_RESOURCE_DIR);
  const sim::SimTrace tr = sim::simulate(sv.model, sv.autopilot, plan.water, sim::resolveScenario(plan, v), plan.options);
  sim::writeSimulatedLog(tr, {v.id, "plan", plan_file, seed, sv.model.thruster_count, installed, {}}, out);
}

// The log import page (current) imports `log_file`; returns when it is done.
void importLog(OperatorWizard& wiz, const std::string& log_file) {
  auto* import = qobject_cast<LogImportPage*>(wiz.currentPage());
  ASSERT_NE(import, nullptr);
  import->startImport(QString::fromStdString(log_file));
  QElapsedTimer t;
  t.start();
  while (import->job().running() && t.elapsed() < 60000) QApplication::processEvents(QEventLoop::AllEvents, 20);
  QApplication::processEvents();
}

bool hasNote(const analysis::AnalysisReport& r, const char* id) {
  for (const Message& n : r.notes)
    if (n.id() == id) return true;
  return false;
}

}  // namespace

class AnalysisInputsWizard : public auv::testing::UiTest {
 protected:
  // The demo configuration in the history and one mission flown with
  // `installed` kg at the four points; returns the log's path.
  std::string seedHistoryAndFly(const std::vector<double>& installed) {
    {
      HistoryStore store(path("history.sqlite").toStdString());
      seedDemoHistory(store, AUV_RESOURCE_DIR, makeUtc(2026, 4, 30, 9, 0, 0));
    }
    const std::string log_file = path("mission.csv").toStdString();
    simulateMission(installed, 21, log_file);
    return log_file;
  }

  // A post-mission session of the demo configuration (in the history) with
  // `log_file` imported and `installed` typed into the installed fields;
  // returns the wizard on the analysis page.
  std::unique_ptr<OperatorWizard> analyse(const std::string& log_file, const std::vector<double>& installed,
                                          const QString& level_check = QString()) {
    WizardState s = makeDemoState(AUV_RESOURCE_DIR);
    s.configuration_in_history = true;
    s.mode = SessionMode::kPostMission;
    auto wiz = std::make_unique<OperatorWizard>(std::move(s));
    wiz->setClock(fixedNow);
    wiz->setAutosaveEnabled(false);
    wiz->resize(1000, 760);
    wiz->show();
    wiz->next();
    wiz->next();
    EXPECT_EQ(wiz->currentId(), OperatorWizard::kLogImport);
    if (wiz->currentId() != OperatorWizard::kLogImport) return wiz;
    importLog(*wiz, log_file);
    for (std::size_t i = 0; i < 4; ++i)
      auv::testing::typeInto(find<NumberInput>(*wiz, kInstalledFields[i]), QString::number(installed[i]));
    if (!level_check.isEmpty()) auv::testing::typeInto(find<NumberInput>(*wiz, "pitch_alignment_sigma_deg"), level_check);
    wiz->next();
    EXPECT_EQ(wiz->currentId(), OperatorWizard::kDeviationPlots);
    return wiz;
  }
};

TEST_F(AnalysisInputsWizard, TheSecondMissionCalibratesWithTheFirst) {
  {
    HistoryStore store(path("history.sqlite").toStdString());
    seedDemoHistory(store, AUV_RESOURCE_DIR, makeUtc(2026, 4, 30, 9, 0, 0));
  }
  const std::vector<double> first{7.2, 7.2, 25.2, 25.2}, second{14.4, 14.4, 19.2, 19.2};
  const std::string log1 = path("mission1.csv").toStdString(), log2 = path("mission2.csv").toStdString();
  simulateMission(first, 21, log1);
  simulateMission(second, 22, log2);

  analysis::AnalysisReport alone;
  {
    auto wiz = analyse(log1, first);
    ASSERT_TRUE(wiz->state().analysis.has_value());
    alone = *wiz->state().analysis;
    EXPECT_FALSE(hasNote(alone, "analysis.history_calibration"));  // nothing analysed before it
    HistoryStore store(path("history.sqlite").toStdString());
    saveMissionToHistory(store, wiz->state(), fixedNow());
  }
  auto wiz = analyse(log2, second);
  ASSERT_TRUE(wiz->state().analysis.has_value());
  const analysis::AnalysisReport& joint = *wiz->state().analysis;
  EXPECT_TRUE(hasNote(joint, "analysis.history_calibration"));
  EXPECT_GT(joint.details["auv_estimate"].value("history_segments_used", 0), 0);
  EXPECT_NE(find<QLabel>(*wiz, "analysis_notes")->text().indexOf("earlier missions of this configuration"), -1)
      << find<QLabel>(*wiz, "analysis_notes")->text().toStdString();
  const QString source = wiz->currentPage()->findChild<QLabel*>("plan_estimate_source")->text();
  EXPECT_NE(source.indexOf("this log and the configuration's earlier mission"), -1) << source.toStdString();

  // The same joint analysis through core, and the truth.
  const VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000");
  const MissionLog log = readInterchangeCsv(log2);
  analysis::AnalysisOptions o;
  o.log_name = "mission2.csv";
  o.installed_kg = second;
  HistoryStore store(path("history.sqlite").toStdString());
  o.history = historyCalibrationMissions(store, wiz->state().configuration_id, v, fixedNow(), o.log_name);
  ASSERT_EQ(o.history.size(), 1u);
  EXPECT_EQ(o.history[0].installed_kg, first);
  const analysis::AnalysisReport core = analysis::analyzeMission(log, v, o);
  EXPECT_NEAR(joint.net_buoyancy_kg.value, core.net_buoyancy_kg.value, 1e-9);
  EXPECT_NEAR(joint.cg_x_mm.value, core.cg_x_mm.value, 1e-9);
  const double truth = std::stod(*log.metadataValue("truth_net_buoyancy_kg"));
  EXPECT_LE(std::abs(joint.net_buoyancy_kg.value - truth), 2.0 * joint.net_buoyancy_kg.sigma + 0.01)
      << joint.net_buoyancy_kg.value << " +- " << joint.net_buoyancy_kg.sigma << " truth " << truth;
  EXPECT_LT(joint.net_buoyancy_kg.sigma, alone.net_buoyancy_kg.sigma);
}

// Typed key by key: a level check of +-0.1 deg becomes the prior on the
// sensor's bias (the analysis as core runs it with that prior), the session
// keeps it, and a value out of range is refused on the page with the fix.
TEST_F(AnalysisInputsWizard, APitchLevelCheckNarrowsTheSensorsPrior) {
  const std::vector<double> installed{7.2, 7.2, 25.2, 25.2};
  const std::string log_file = seedHistoryAndFly(installed);
  double unchecked_sigma_kg = 0.0;
  {
    auto unchecked = analyse(log_file, installed);
    ASSERT_TRUE(unchecked->state().analysis.has_value());
    EXPECT_FALSE(unchecked->state().pitch_alignment_sigma_deg.has_value());
    const analysis::CalibrationParameter* wide =
        analysis::calibrationParameter(*unchecked->state().analysis, "pitch_sensor_bias");
    ASSERT_NE(wide, nullptr);
    EXPECT_DOUBLE_EQ(wide->prior_sigma, 1.0);  // not checked: an AHRS nobody aligned
    unchecked_sigma_kg = unchecked->state().analysis->net_buoyancy_kg.sigma;
  }

  auto wiz = analyse(log_file, installed, "0.1");
  ASSERT_EQ(wiz->state().pitch_alignment_sigma_deg, std::optional<double>(0.1));
  ASSERT_TRUE(wiz->state().analysis.has_value());
  const analysis::AnalysisReport& r = *wiz->state().analysis;
  const analysis::CalibrationParameter* bias = analysis::calibrationParameter(r, "pitch_sensor_bias");
  ASSERT_NE(bias, nullptr);
  EXPECT_DOUBLE_EQ(bias->prior_sigma, 0.1);
  const VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000");
  analysis::AnalysisOptions o;
  o.log_name = "mission.csv";
  o.installed_kg = installed;
  o.pitch_alignment_sigma_deg = 0.1;
  const analysis::AnalysisReport core = analysis::analyzeMission(readInterchangeCsv(log_file), v, o);
  EXPECT_NEAR(r.net_buoyancy_kg.value, core.net_buoyancy_kg.value, 1e-9);
  EXPECT_NEAR(r.net_buoyancy_kg.sigma, core.net_buoyancy_kg.sigma, 1e-9);
  EXPECT_LE(r.net_buoyancy_kg.sigma, unchecked_sigma_kg);

  // The session keeps it; a resumed session shows it in the field.
  const nlohmann::json saved = sessionToJson(wiz->state(), OperatorWizard::kDeviationPlots, "2026-05-20T12:00:00Z");
  EXPECT_DOUBLE_EQ(saved.at("pitch_alignment_sigma_deg").get<double>(), 0.1);
  const SavedSession back = sessionFromJson(saved.dump(), "session.json", AUV_RESOURCE_DIR);
  EXPECT_EQ(back.state.pitch_alignment_sigma_deg, std::optional<double>(0.1));
  nlohmann::json bad = saved;
  bad["pitch_alignment_sigma_deg"] = 9.0;
  EXPECT_THROW(sessionFromJson(bad.dump(), "session.json", AUV_RESOURCE_DIR), InputError);

  // Out of range on the page: it stays, and says what to enter.
  wiz->back();
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kLogImport);
  EXPECT_EQ(find<NumberInput>(*wiz, "pitch_alignment_sigma_deg")->value(), 0.1);
  auv::testing::typeInto(find<NumberInput>(*wiz, "pitch_alignment_sigma_deg"), "7");
  wiz->next();
  EXPECT_EQ(wiz->currentId(), OperatorWizard::kLogImport);
  const QString error = wiz->currentPage()->findChild<QLabel*>("error")->text();
  EXPECT_TRUE(error.startsWith("Pitch sensor level check, within ±: ")) << error.toStdString();
  EXPECT_NE(error.indexOf("5"), -1) << error.toStdString();  // the limit
  auv::testing::typeInto(find<NumberInput>(*wiz, "pitch_alignment_sigma_deg"), "0.2");
  wiz->next();
  EXPECT_EQ(wiz->currentId(), OperatorWizard::kDeviationPlots);
  EXPECT_EQ(wiz->state().pitch_alignment_sigma_deg, std::optional<double>(0.2));
}

// The level check belongs to the configuration, like its BG: saved with the
// mission, filled in when the configuration is picked again (by mouse, as a
// technician does), and cleared by a 0 ("not checked") after a remount.
TEST_F(AnalysisInputsWizard, TheLevelCheckStaysWithTheConfiguration) {
  const std::vector<double> installed{7.2, 7.2, 25.2, 25.2};
  const std::string log_file = seedHistoryAndFly(installed);
  std::string config_id;
  {
    auto wiz = analyse(log_file, installed, "0.1");
    config_id = wiz->state().configuration_id;
    saveMissionToHistory(*wiz->history(), wiz->state(), fixedNow());
  }
  {
    HistoryStore store(path("history.sqlite").toStdString());
    ASSERT_TRUE(store.configuration(config_id)->pitch_level_check_deg.has_value());
    EXPECT_DOUBLE_EQ(*store.configuration(config_id)->pitch_level_check_deg, 0.1);
  }

  // Picked again from the start page: row, Post mission, Next, Next.
  OperatorWizard again(makeEmptyState(AUV_RESOURCE_DIR));
  again.setClock(fixedNow);
  again.setAutosaveEnabled(false);
  again.resize(1000, 760);
  again.show();
  auto* table = find<QTableWidget>(again, "configurations");
  int row = -1;
  for (int r = 0; r < table->rowCount(); ++r)
    if (table->item(r, 0) && table->item(r, 0)->text() == QString::fromStdString(config_id)) row = r;
  ASSERT_GE(row, 0);
  const QRect cell = table->visualItemRect(table->item(row, 0));
  QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
  auto* post = find<QRadioButton>(again, "mode_post");
  QTest::mouseClick(post, Qt::LeftButton, Qt::NoModifier, QPoint(8, post->height() / 2));
  ASSERT_TRUE(post->isChecked());
  QTest::mouseClick(again.button(QWizard::NextButton), Qt::LeftButton);
  QTest::mouseClick(again.button(QWizard::NextButton), Qt::LeftButton);
  ASSERT_EQ(again.currentId(), OperatorWizard::kLogImport);
  auto* field = find<NumberInput>(again, "pitch_alignment_sigma_deg");
  EXPECT_DOUBLE_EQ(field->value(), 0.1);
  EXPECT_EQ(field->text(), "0.10");

  // The sensor was remounted: 0 = not checked, saved with the next mission.
  const std::string log2 = path("mission2.csv").toStdString();
  simulateMission(installed, 22, log2);
  importLog(again, log2);
  auv::testing::typeInto(field, "0");
  QTest::mouseClick(again.button(QWizard::NextButton), Qt::LeftButton);
  ASSERT_EQ(again.currentId(), OperatorWizard::kDeviationPlots);
  EXPECT_FALSE(again.state().pitch_alignment_sigma_deg.has_value());
  saveMissionToHistory(*again.history(), again.state(), fixedNow() + std::chrono::hours(1));
  HistoryStore store(path("history.sqlite").toStdString());
  EXPECT_FALSE(store.configuration(config_id)->pitch_level_check_deg.has_value());
}

}  // namespace auv::ui
