// The glider post-mission -> pre-mission sequence of the wizard (issue 12
// item 6) on the bundled Slocum log, driven as a person does: Next clicked,
// target choices clicked, target values typed key by key. The grams shown
// are checked against the CLI's own path through core (`model-check
// --target-...`: analyzeMission with the target flags, the model check, the
// joint answer, planGliderBallast), run here independently of the wizard.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QtTest/QTest>
#include <cmath>
#include <fstream>

#include "analysis/mission_analysis.h"
#include "discrepancy/glider_ballast_answer.h"
#include "discrepancy/glider_check_model.h"
#include "discrepancy/model_check_report.h"
#include "discrepancy/vehicle_check.h"
#include "history/store.h"
#include "missionlog/interchange_csv.h"
#include "pages/glider_ballast_page.h"
#include "pages/glider_pre_mission_page.h"
#include "pages/model_check_page.h"
#include "planning/glider_ballast_plan.h"
#include "screenshot.h"
#include "sim/glider_model.h"
#include "sim/glider_simulator.h"
#include "sim/mission_plan.h"
#include "sim/sim_log.h"
#include "vehicle/json_reader.h"
#include "typing.h"
#include "ui_fixture.h"
#include "vehicle/vehicle_catalog.h"
#include "seawater/seawater.h"
#include "widgets/glider_ballast_map.h"
#include "widgets/inputs.h"
#include "wizard/advice_text.h"
#include "wizard/demo_state.h"
#include "wizard/glider_work_order.h"
#include "wizard/operator_wizard.h"
#include "wizard/translations.h"

namespace auv::ui {
using auv::testing::find;
using auv::testing::shot;
using auv::testing::typeInto;

namespace {

const std::string kLog = std::string(AUV_RESOURCE_DIR) + "/examples/slocum_g2_model-check_compressibility.csv";

// `auvballast model-check --vehicle slocum_g2 --log <log> [--target-...]`,
// the recommendation part, through the same core calls as cmd_model_check.cpp.
nlohmann::json cliAnswer(const MissionLog& log, const analysis::GliderTargetRequest& q, const std::string& vehicle = "slocum_g2",
                         const std::vector<double>& installed = {}) {
  const VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load(vehicle);
  analysis::AnalysisOptions a;
  a.glider_target = q;
  const analysis::AnalysisReport r = analysis::analyzeMission(log, v, a);
  nlohmann::json j = analysis::toJson(r);
  const auto model = discrepancy::makeCheckModel(log, v, AUV_RESOURCE_DIR);
  const discrepancy::ModelCheckResult mc = discrepancy::runModelCheck(*model);
  discrepancy::mergeIntoAnalysisJson(j, mc);
  const auto* glider = dynamic_cast<const discrepancy::GliderCheckModel*>(model.get());
  EXPECT_NE(glider, nullptr);
  const analysis::GliderTarget target{r.target_density_kgm3, r.target_pressure_dbar, r.target_temperature_degC, NAN,
                                      r.target_basis};
  discrepancy::mergeGliderAnswer(j, discrepancy::gliderBallastAnswer(*glider, mc, target));
  return planGliderBallast(v, {j, installed, std::nullopt});
}

// The Slocum's bottles as the history has them (profile order): bow bottles
// nearly full, so the bow cannot take its whole share.
const std::vector<double> kInstalled = {0.43, 0.43, 0.10, 0.10, 0.06, 0.06};

void seedSlocumHistory(const QString& file) {
  HistoryStore store(file.toStdString());
  Configuration c;
  c.config_id = "49-1-1";
  c.vehicle_key = "slocum_g2";
  c.vehicle_name = "Slocum G2 electric glider";
  c.created_at = makeUtc(2026, 5, 1);
  store.addConfiguration(c);
  const VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("slocum_g2");
  InstalledState st;
  st.installed_at = makeUtc(2026, 5, 2);
  for (std::size_t i = 0; i < v.points.size(); ++i) st.points.push_back({v.points[i].name, kInstalled[i], {}});
  store.addInstalledState("49-1-1", st);
}

// The signed grams after "add" in the page's result line.
double shownGrams(const QString& text) {
  const auto m = QRegularExpression(R"(add\s*(?:<b>)?\s*([+-]?\d+))").match(text);
  EXPECT_TRUE(m.hasMatch()) << text.toStdString();
  return m.hasMatch() ? m.captured(1).toDouble() : NAN;
}

void clickRadio(QRadioButton* r) {
  QTest::mouseClick(r, Qt::LeftButton, Qt::NoModifier, QPoint(8, r->height() / 2));
  QApplication::processEvents();
  ASSERT_TRUE(r->isChecked()) << r->objectName().toStdString();
}

}  // namespace

class GliderSequence : public auv::testing::UiTest {
 protected:
  static void waitFor(const std::function<bool()>& busy) {
    QElapsedTimer t;
    t.start();
    while (busy() && t.elapsed() < 300000) QApplication::processEvents(QEventLoop::AllEvents, 20);
    QApplication::processEvents();
  }
  static void clickNext(OperatorWizard& w) {
    QTest::mouseClick(w.button(QWizard::NextButton), Qt::LeftButton);
    QApplication::processEvents();
  }
};

TEST_F(GliderSequence, SlocumLogToGramsPerBottleTypedTargetsMatchTheCli) {
  seedSlocumHistory(path("history.sqlite"));
  WizardState s = makeSlocumDemoState(AUV_RESOURCE_DIR);
  ASSERT_EQ(s.configuration_id, "49-1-1");
  s.configuration_in_history = true;
  s.mode = SessionMode::kPostMission;
  s.log = std::make_shared<MissionLog>(readInterchangeCsv(kLog));
  s.log_file = kLog;
  s.log_format = "mission-log CSV v1";
  s.log_report = ReadReport{};
  const MissionLog& log = *s.log;
  auto wiz = std::make_unique<OperatorWizard>(std::move(s));
  wiz->setClock(fixedNow);
  wiz->setAutosaveEnabled(false);
  wiz->resize(1000, 760);
  wiz->show();
  wiz->next();
  wiz->next();
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kLogImport);
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kDeviationPlots);
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kModelCheck);
  auto* m = qobject_cast<ModelCheckPage*>(wiz->currentPage());
  waitFor([m] { return m->job().running(); });
  ASSERT_TRUE(wiz->state().model_check.has_value());
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kGliderPreMission);
  auto* page = qobject_cast<GliderPreMissionPage*>(wiz->currentPage());

  // What the log showed: the analysis's grams and the term the check used.
  EXPECT_NE(find<QLabel>(*wiz, "log_answer")->text().indexOf(signedFixed(wiz->state().analysis->mass_to_add_g.value, 0)), -1)
      << find<QLabel>(*wiz, "log_answer")->text().toStdString();
  EXPECT_NE(find<QLabel>(*wiz, "terms_used")->text().indexOf("hull compressibility"), -1);
  // What the bottles hold now, from the history.
  EXPECT_NE(find<QLabel>(*wiz, "glider_installed_now")->text().indexOf("Installed now (history, 2026-05-02): Bow bottle / port " + massText(0.43, true)), -1)
      << find<QLabel>(*wiz, "glider_installed_now")->text().toStdString();

  // Default: the log's own water at its deepest yo, and the page says so.
  EXPECT_TRUE(find<QRadioButton>(*wiz, "target_log")->isChecked());
  EXPECT_NE(find<QLabel>(*wiz, "target_resolved")->text().indexOf("default: the log's own water at the bottom of its deepest yo"), -1)
      << find<QLabel>(*wiz, "target_resolved")->text().toStdString();
  const nlohmann::json def = cliAnswer(log, {}, "slocum_g2", kInstalled);
  EXPECT_EQ(shownGrams(find<QLabel>(*wiz, "glider_result")->text()), std::round(def["mass_to_add_g"].get<double>()));
  shot(*wiz, "70_glider_pre_mission");

  // A depth in the log's own CTD profile, typed.
  clickRadio(find<QRadioButton>(*wiz, "target_depth_choice"));
  typeInto(find<NumberInput>(*wiz, "glider_target_depth"), "100");
  analysis::GliderTargetRequest q;
  q.depth_m = 100.0;
  const nlohmann::json atDepth = cliAnswer(log, q, "slocum_g2", kInstalled);
  EXPECT_EQ(shownGrams(find<QLabel>(*wiz, "glider_result")->text()), std::round(atDepth["mass_to_add_g"].get<double>()));
  EXPECT_NE(find<QLabel>(*wiz, "target_resolved")->text().indexOf("CTD at 100.0 m"), -1);

  // A density, typed.
  clickRadio(find<QRadioButton>(*wiz, "target_density_choice"));
  typeInto(find<NumberInput>(*wiz, "glider_target_density"), "1027.3");
  EXPECT_EQ(find<NumberInput>(*wiz, "glider_target_density")->value(), 1027.3);
  EXPECT_EQ(page->choice().density_kgm3, 1027.3);
  EXPECT_EQ(static_cast<int>(page->choice().kind), 1);
  q = {};
  q.density_kgm3 = 1027.3;
  const nlohmann::json atDensity = cliAnswer(log, q, "slocum_g2", kInstalled);
  EXPECT_EQ(shownGrams(find<QLabel>(*wiz, "glider_result")->text()), std::round(atDensity["mass_to_add_g"].get<double>()))
      << find<QLabel>(*wiz, "target_resolved")->text().toStdString() << " / " << atDensity["target"].dump();

  // Pressure and temperature (deeper and colder than the log), then a salinity.
  clickRadio(find<QRadioButton>(*wiz, "target_pt_choice"));
  typeInto(find<NumberInput>(*wiz, "glider_target_pressure"), "180");
  typeInto(find<NumberInput>(*wiz, "glider_target_temperature"), "6.5");
  q = {};
  q.pressure_dbar = 180.0;
  q.temperature_degC = 6.5;
  const nlohmann::json atPT = cliAnswer(log, q, "slocum_g2", kInstalled);
  EXPECT_EQ(shownGrams(find<QLabel>(*wiz, "glider_result")->text()), std::round(atPT["mass_to_add_g"].get<double>()));
  typeInto(find<NumberInput>(*wiz, "glider_target_salinity"), "35.2");
  q.density_kgm3 = seawater::density(35.2, 6.5, 180.0);
  const nlohmann::json oracle = cliAnswer(log, q, "slocum_g2", kInstalled);
  EXPECT_EQ(shownGrams(find<QLabel>(*wiz, "glider_result")->text()), std::round(oracle["mass_to_add_g"].get<double>()));
  // Different targets, different answers (the test would see a page that ignores them).
  EXPECT_NE(std::round(atPT["mass_to_add_g"].get<double>()), std::round(def["mass_to_add_g"].get<double>()));
  EXPECT_NE(std::round(atDensity["mass_to_add_g"].get<double>()), std::round(def["mass_to_add_g"].get<double>()));
  EXPECT_EQ(page->answer().plan["points"], oracle["points"]);

  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kGliderBallast);
  // Grams per bottle in words, each the core's figure.
  const QString steps = find<QLabel>(*wiz, "glider_steps")->text();
  int changed = 0;
  for (const auto& p : oracle["points"]) {
    const double g = p["add_g"].get<double>();
    if (g == 0.0) continue;
    ++changed;
    const QString want = QString("%1: %2 %3 g").arg(QString::fromStdString(p["label"].get<std::string>()),
                                                   g > 0 ? "add" : "take out").arg(std::abs(g), 0, 'f', 0);
    EXPECT_NE(steps.indexOf(want), -1) << want.toStdString() << " in " << steps.toStdString();
  }
  EXPECT_GT(changed, 0);
  EXPECT_NE(steps.indexOf(QString("%1 g in all").arg(signedFixed(oracle["total_change_g"].get<double>(), 0))), -1)
      << steps.toStdString();
  // The map: one place per bottle and rail with the same grams, labels apart.
  auto* map = find<GliderBallastMap>(*wiz, "glider_map");
  ASSERT_EQ(map->model().places.size(), oracle["points"].size());
  for (std::size_t i = 0; i < map->model().places.size(); ++i) {
    EXPECT_EQ(map->model().places[i].add_g, oracle["points"][i]["add_g"].get<double>());
    // Capacities respected: what each place holds afterwards, against what it can.
    EXPECT_EQ(map->model().places[i].after_g, std::round(1000 * kInstalled[i]) + oracle["points"][i]["add_g"].get<double>());
    EXPECT_LE(map->model().places[i].after_g, oracle["points"][i]["capacity_g"].get<double>());
  }
  // The bow is nearly full: it cannot take Baird's share, and the page says what core warned.
  EXPECT_LE(oracle["points"][0]["add_g"].get<double>(), 20.0);
  ASSERT_FALSE(oracle["warnings"].empty());
  // In the wizard's words (by the message id core gives beside the English).
  const nlohmann::json& wid = oracle["warnings_ids"][0];
  EXPECT_EQ(wid["id"].get<std::string>(), "weighing.bottles_not_level");
  const Message warned(wid["id"].get<std::string>(), oracle["warnings"][0].get<std::string>(),
                       wid["args"].get<std::vector<std::string>>());
  EXPECT_NE(find<QLabel>(*wiz, "glider_notes")->text().indexOf(adviceText(warned).toHtmlEscaped()), -1)
      << find<QLabel>(*wiz, "glider_notes")->text().toStdString();
  shot(*wiz, "71_glider_ballast");
  const auto& rects = map->labelRects();
  ASSERT_EQ(rects.size(), 2 * oracle["points"].size());
  for (std::size_t i = 0; i < rects.size(); ++i)
    for (std::size_t k = i + 1; k < rects.size(); ++k) EXPECT_FALSE(rects[i].intersects(rects[k])) << i << " " << k;
  // The work order lists the same grams.
  const WorkOrder wo = makeGliderWorkOrder(wiz->state(), fixedNow());
  ASSERT_EQ(wo.rows.size(), oracle["points"].size());
  for (std::size_t i = 0; i < wo.rows.size(); ++i)
    EXPECT_EQ(wo.rows[i][1], QString("%1 g").arg(signedFixed(oracle["points"][i]["add_g"].get<double>(), 0)));
  auto* bp = qobject_cast<GliderBallastPage*>(wiz->currentPage());
  EXPECT_EQ(bp->exportWorkOrder(path("work_order.pdf")), QString());
  EXPECT_GT(QFileInfo(path("work_order.pdf")).size(), 1000);
  const QImage order = renderWorkOrder(wo);
  order.save(QString(AUV_SCREENSHOT_DIR) + "/72_glider_work_order.png");

  // Fits a 1366 x 768 laptop screen.
  EXPECT_LE(wiz->minimumSizeHint().height(), 768);

  // Finish saves the mission.
  QTest::mouseClick(wiz->button(QWizard::FinishButton), Qt::LeftButton);
  QApplication::processEvents();
  EXPECT_EQ(wiz->result(), QDialog::Accepted);
  HistoryStore store(path("history.sqlite").toStdString());
  int missions = 0;
  for (const auto& e : store.history(wiz->state().configuration_id)) missions += e.kind == EventKind::kMission;
  EXPECT_EQ(missions, 1);
}

// A Seaglider mission made with the project's own simulator (no Seaglider log
// is bundled): the bundled Slocum yo plan, 1.5 h, flown by the seaglider
// profile with the simulator's steady-glide constants (the profile has no
// "glider_flight" section; the analysis then fits its own hd_a/b/c form to it).
std::string simulateSeagliderMission(const QString& dir) {
  const std::string vehicles = std::string(AUV_RESOURCE_DIR) + "/vehicles/";
  nlohmann::json sg = JsonReader::parseFile(vehicles + "seaglider.json");
  sg["glider_flight"] = JsonReader::parseFile(vehicles + "slocum_g2.json")["glider_flight"];
  const std::string profile = (dir + "/seaglider_sim.json").toStdString();
  std::ofstream(profile) << sg.dump(1);
  const VehicleProfile v = VehicleCatalog(vehicles).load(profile);
  const std::string plan_file = std::string(AUV_RESOURCE_DIR) + "/examples/slocum_g2_yo.plan.json";
  nlohmann::json doc = JsonReader::parseFile(plan_file);
  doc["vehicle"] = profile;
  doc["legs"][0]["duration_s"] = 5400.0;
  doc["legs"][0]["dive_to_m"] = 180.0;
  doc["options"]["trace_interval_s"] = 4.0;
  const sim::MissionPlan plan = sim::parseMissionPlan(doc, plan_file);
  const auto tr = sim::simulateGlider(sim::loadGliderModel(v), plan.water, sim::resolveGliderScenario(plan, v), plan.options);
  const std::string out = (dir + "/sg_mission.csv").toStdString();
  sim::writeSimulatedLog(tr, {"seaglider", "plan", plan_file, plan.options.seed, 0, {}, {}}, out);
  return out;
}

TEST_F(GliderSequence, SeagliderLeadAndVbdFromItsOwnLog) {
  const std::string file = simulateSeagliderMission(dirPath());
  WizardState s = makeSlocumDemoState(AUV_RESOURCE_DIR);
  s.vehicle = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("seaglider");
  s.configuration_id = "171-1-1";
  s.mode = SessionMode::kPostMission;
  s.log = std::make_shared<MissionLog>(readInterchangeCsv(file));
  s.log_file = file;
  s.log_format = "mission-log CSV v1";
  s.log_report = ReadReport{};
  const MissionLog& log = *s.log;
  auto wiz = std::make_unique<OperatorWizard>(std::move(s));
  wiz->setClock(fixedNow);
  wiz->setAutosaveEnabled(false);
  wiz->resize(1000, 760);
  wiz->show();
  wiz->next();
  wiz->next();
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kLogImport);
  clickNext(*wiz);
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kModelCheck);
  auto* m = qobject_cast<ModelCheckPage*>(wiz->currentPage());
  waitFor([m] { return m->job().running(); });
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kGliderPreMission);
  // The next deployment 10 m shallower than the log's deepest yo, typed.
  clickRadio(find<QRadioButton>(*wiz, "target_depth_choice"));
  typeInto(find<NumberInput>(*wiz, "glider_target_depth"), "170");
  analysis::GliderTargetRequest q;
  q.depth_m = 170.0;
  const nlohmann::json oracle = cliAnswer(log, q, "seaglider");
  EXPECT_EQ(shownGrams(find<QLabel>(*wiz, "glider_result")->text()), std::round(oracle["mass_to_add_g"].get<double>()));
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kGliderBallast);
  const auto& sgo = oracle["seaglider"];
  const QString steps = find<QLabel>(*wiz, "glider_steps")->text();
  EXPECT_NE(steps.indexOf(QString("Set $C_VBD from 2680 to %1").arg(sgo["C_VBD_new"].get<double>(), 0, 'f', 0)), -1) << steps.toStdString();
  const double lead = sgo["lead_change_g"].get<double>();
  EXPECT_NE(steps.indexOf(lead == 0.0 ? QString("Lead: no change") : QString("Lead: %1 %2 g").arg(lead > 0 ? "add" : "take off").arg(std::abs(lead), 0, 'f', 0)), -1)
      << steps.toStdString();
  // $C_PITCH: set when the pitch mass can reach it, else kept and said why
  // (this log's pitch battery is a Slocum's, so its trim need not fit).
  const double cp = sgo["C_PITCH_new"].get<double>();
  const bool reachable = cp >= 230.0 && cp <= 3900.0;  // seaglider.json PITCH_MIN .. PITCH_MAX
  EXPECT_NE(steps.indexOf(reachable ? QString("Set $C_PITCH from 2145 to %1").arg(cp, 0, 'f', 0)
                                    : QString("Keep $C_PITCH at 2145: the log's pitch trim gives %1").arg(cp, 0, 'f', 0)),
            -1)
      << steps.toStdString();
  EXPECT_NE(find<GliderBallastMap>(*wiz, "glider_map")->model().note.indexOf(QString("%1").arg(sgo["C_VBD_new"].get<double>(), 0, 'f', 0)), -1);
  shot(*wiz, "73_glider_ballast_seaglider");
  QTest::mouseClick(wiz->button(QWizard::FinishButton), Qt::LeftButton);
  QApplication::processEvents();
  EXPECT_EQ(wiz->result(), QDialog::Accepted);
}

// SeaExplorer (no bundled log; a profile without Slocum bottles or Seaglider
// VBD): the page says the mass change and everything core cannot tell, and
// the map draws no invented places.
TEST_F(GliderSequence, SeaExplorerSaysWhatItCannotTell) {
  VehicleProfile v = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("slocum_g2");
  v.sections.erase("slocum");
  v.sections["seaexplorer"] = nlohmann::json::object();
  const nlohmann::json report = {
      {"mass_to_add_g", -37.4}, {"mass_to_add_sigma_g", 6.0},
      {"target", {{"density_kgm3", 1027.5}, {"pressure_dbar", 300.0}, {"temperature_degC", 4.0}, {"basis", "x"}}},
      {"details", {{"glider_trim", {{"pitch", {{"T1_per_cm3", 0.001}, {"T2_per_mm", -0.02}, {"T3", 0.31}}}}}}}};
  const nlohmann::json plan = planGliderBallast(v, {report, {}, std::nullopt});
  ASSERT_EQ(plan["vehicle_type"], "seaexplorer");
  const GliderInstructions in = gliderInstructions(plan, &v);
  EXPECT_TRUE(in.steps.contains("Change the glider's mass by -37 g at its ballast places so that it stays level."))
      << in.steps.join("\n").toStdString();
  EXPECT_TRUE(in.steps.contains(QString("Linear battery for level flight at pump zero: %1 mm.")
                                    .arg(plan["linear_battery_for_level_mm"].get<double>(), 0, 'f', 1)));
  ASSERT_EQ(in.cannot_tell.size(), static_cast<qsizetype>(plan["cannot_tell"].size()));
  EXPECT_GE(in.cannot_tell.size(), 2);
  const GliderMapModel m = makeGliderMapModel(v, plan);
  EXPECT_TRUE(m.places.empty());
  EXPECT_NE(m.note.indexOf("does not tell where the grams go"), -1);
}

// A log too short for the glide fit: no grams to plan, so the target page is
// the last one and Finish saves the mission alone.
TEST_F(GliderSequence, LogWithoutNetBuoyancyFinishesAndSaves) {
  const std::string short_log = path("short.csv").toStdString();
  {
    std::ifstream in(kLog);
    std::ofstream out(short_log);
    std::string line;
    for (int n = 0; n < 40 && std::getline(in, line); ++n) out << line << "\n";
  }
  WizardState s = makeSlocumDemoState(AUV_RESOURCE_DIR);
  s.mode = SessionMode::kPostMission;
  s.log = std::make_shared<MissionLog>(readInterchangeCsv(short_log));
  s.log_file = short_log;
  s.log_format = "mission-log CSV v1";
  s.log_report = ReadReport{};
  auto wiz = std::make_unique<OperatorWizard>(std::move(s));
  wiz->setClock(fixedNow);
  wiz->setAutosaveEnabled(false);
  wiz->resize(1000, 760);
  wiz->show();
  wiz->next();
  wiz->next();
  clickNext(*wiz);
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kModelCheck);
  auto* m = qobject_cast<ModelCheckPage*>(wiz->currentPage());
  waitFor([m] { return m->job().running(); });
  clickNext(*wiz);
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kGliderPreMission);
  ASSERT_FALSE(wiz->state().analysis->mass_to_add_g.known);
  EXPECT_NE(find<QLabel>(*wiz, "log_answer")->text().indexOf("does not show the glider's net buoyancy"), -1);
  EXPECT_EQ(wiz->currentPage()->nextId(), -1);
  EXPECT_TRUE(wiz->currentPage()->isComplete());
  QTest::mouseClick(wiz->button(QWizard::FinishButton), Qt::LeftButton);
  QApplication::processEvents();
  EXPECT_EQ(wiz->result(), QDialog::Accepted);
  HistoryStore store(path("history.sqlite").toStdString());
  int missions = 0;
  for (const auto& e : store.history("49-1-1")) missions += e.kind == EventKind::kMission;
  EXPECT_EQ(missions, 1);
}

TEST_F(GliderSequence, NorwegianWordsOnTheGliderPagesAndSteps) {
  ASSERT_TRUE(installTranslation(QLocale(QLocale::NorwegianBokmal)));
  {
    OperatorWizard wiz(makeSlocumDemoState(AUV_RESOURCE_DIR));
    EXPECT_EQ(wiz.page(OperatorWizard::kGliderPreMission)->title(), "Glider: vannet ved neste utsetting");
    EXPECT_EQ(wiz.page(OperatorWizard::kGliderBallast)->title(), "Glider: hvor grammene skal");
    // The steps of a core answer (+120 g, Baird's level split) in Norwegian.
    const VehicleProfile& v = *wiz.state().vehicle;
    const nlohmann::json report = {{"mass_to_add_g", 120.0}, {"mass_to_add_sigma_g", 5.0},
                                   {"target", {{"density_kgm3", 1026.0}, {"pressure_dbar", 100.0}, {"temperature_degC", 8.0}, {"basis", "x"}}}};
    const nlohmann::json plan = planGliderBallast(v, {report, {}, std::nullopt});
    const GliderInstructions in = gliderInstructions(plan, &v);
    ASSERT_FALSE(in.steps.isEmpty());
    const auto& first = plan["points"][0];
    EXPECT_EQ(in.steps[0], QString("%1: legg i %2 g blyhagl (rommer høyst 450 g).")
                               .arg(QString::fromStdString(first["label"].get<std::string>()))
                               .arg(first["add_g"].get<double>(), 0, 'f', 0));
    EXPECT_TRUE(in.headline.startsWith("Masse å legge til +120 ± 5 g")) << in.headline.toStdString();
  }
  removeTranslation();
}

}  // namespace auv::ui
