// The pre-mission sequence (start -> vehicle -> pre mission -> adjustment ->
// summary) on a real analysis of the bundled simulated HUGIN mission. Every
// number on screen is checked against core's planPreMission run here
// independently from the same records; the work order is checked as a PDF
// file and by the strings its drawing sends to the paint engine.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QCheckBox>
#include "widgets/number_input.h"
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPainter>
#include <QRadioButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest/QTest>
#include <cmath>

#include "history/store.h"
#include "pages/adjustment_page.h"
#include "pages/pre_mission_page.h"
#include "pages/summary_page.h"
#include "planning/installed_prediction.h"
#include "planning/plan_sources.h"
#include "pre_mission_fixture.h"
#include "screenshot.h"
#include "typing.h"
#include "ui_fixture.h"
#include "vehicle/json_reader.h"
#include "widgets/inputs.h"
#include "widgets/weight_map_widget.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"
#include "wizard/work_order.h"

namespace auv::ui {
using auv::testing::exampleHuginAnalysis;
using auv::testing::exampleInstalledKg;
using auv::testing::find;
using auv::testing::shot;

namespace {

// The number a label or cell starts with ("+0.62 ± 0.15 kg" -> 0.62).
double leadingNumber(const QString& text) {
  const auto m = QRegularExpression(R"([-+−]?\d+(\.\d+)?)").match(text);
  return m.hasMatch() ? QString(m.captured(0)).replace(QChar(0x2212), '-').toDouble() : std::nan("");
}

// The next mission the tests plan for: colder, saltier and deeper than the
// analysed one, with a deeper excursion.
PlannedWater nextWater() {
  PlannedWater w;
  w.temperature_degC = 6.0;
  w.salinity_psu = 35.0;
  w.depth_m = 80.0;
  w.latitude_deg = 60.0;
  return w;
}
constexpr double kDeepest = 150.0;

// The oracle: core's plan from the same analysis, pieces and water, built
// here without the pages.
PreMissionPlan oraclePlan(const VehicleProfile& v) {
  PreMissionInput in;
  in.installed_kg = exampleInstalledKg();
  in.estimate = trimEstimateFromReport(analysis::toJson(exampleHuginAnalysis()), "oracle");
  in.next = nextMissionWater(nextWater(), kDeepest, "operator");
  in.policy = PlanPolicy::Exact;
  return planPreMission(v, in);
}

}  // namespace

class PreMissionPages : public auv::testing::UiTest {
 protected:
  // The HUGIN demo configuration in the history (first mission ten days
  // ago), and a session that has just analysed a mission of it.
  WizardState sessionWithAnalysis() {
    {
      HistoryStore store(path("history.sqlite").toStdString());
      seedDemoHistory(store, AUV_RESOURCE_DIR, fixedNow() - std::chrono::days(10));
    }
    WizardState s = makeDemoState(AUV_RESOURCE_DIR);
    s.configuration_in_history = true;
    s.mode = SessionMode::kPreMission;
    s.analysis = exampleHuginAnalysis();
    s.mission_installed_kg = exampleInstalledKg();
    return s;
  }

  // Walks start -> vehicle -> pre mission and enters the next mission's water.
  static void toPreMissionWithWater(OperatorWizard& wiz) {
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kPreMission);
    find<QRadioButton>(wiz, "water_operator")->setChecked(true);
    find<NumberInput>(wiz, "next_temperature")->setValue(nextWater().temperature_degC);
    find<NumberInput>(wiz, "next_salinity")->setValue(nextWater().salinity_psu);
    find<NumberInput>(wiz, "next_depth")->setValue(nextWater().depth_m);
    find<NumberInput>(wiz, "next_latitude")->setValue(nextWater().latitude_deg);
    find<NumberInput>(wiz, "next_deepest")->setValue(kDeepest);
  }
};

TEST_F(PreMissionPages, PlanFromTheSessionsAnalysisAdjustAndSave) {
  OperatorWizard wiz(sessionWithAnalysis());
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  // The session has an analysis: pre mission is offered and chosen.
  auto* pre = find<QRadioButton>(wiz, "mode_pre");
  EXPECT_TRUE(pre->isEnabled());
  EXPECT_TRUE(pre->isChecked());

  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kPreMission);
  const analysis::AnalysisReport& a = exampleHuginAnalysis();
  ASSERT_TRUE(a.net_buoyancy_kg.known);
  // The estimate as core found it, with its sigma and origin.
  const QString estimate = find<QLabel>(wiz, "estimate")->text();
  const QString net = QString("+%1 ± %2 kg").arg(a.net_buoyancy_kg.value, 0, 'f', 2).arg(a.net_buoyancy_kg.sigma, 0, 'f', 2);
  EXPECT_NE(estimate.indexOf(net), -1) << estimate.toStdString() << " / " << net.toStdString();
  EXPECT_NE(find<QLabel>(wiz, "estimate_source")->text().indexOf("this session's analysis of hugin1000_mission.csv"), -1);
  EXPECT_NE(find<QLabel>(wiz, "installed_now")->text().indexOf("Aft / port 25.2 kg"), -1);
  // Last mission's CTD prefilled: the analysis's water at its operating depth.
  EXPECT_TRUE(find<QRadioButton>(wiz, "water_ctd")->isChecked());
  EXPECT_NEAR(find<NumberInput>(wiz, "next_temperature")->value(), a.temperature_degC.mean, 0.006);
  EXPECT_NEAR(find<NumberInput>(wiz, "next_depth")->value(), a.depth_m.mean, 0.06);
  EXPECT_FALSE(find<NumberInput>(wiz, "next_temperature")->isEnabled());
  // Shown to the CTD's resolution, not every digit of a mean of thousands
  // of samples; the plan takes the exact means.
  for (const char* f : {"next_temperature", "next_salinity"}) {
    const QString t = find<NumberInput>(wiz, f)->lineEdit()->text();
    EXPECT_LE(t.size() - t.indexOf('.') - 1, 3) << f << ": " << t.toStdString();
  }
  for (const char* f : {"next_depth", "next_deepest"}) {
    const QString t = find<NumberInput>(wiz, f)->lineEdit()->text();
    EXPECT_LE(t.size() - t.indexOf('.') - 1, 1) << f << ": " << t.toStdString();
  }
  ASSERT_TRUE(wiz.state().next_water.has_value());
  // (to the report's 6 decimals: the estimate passes through its JSON)
  EXPECT_NEAR(wiz.state().next_water->temperature_degC, a.temperature_degC.mean, 1e-6);
  EXPECT_NEAR(wiz.state().next_water->salinity_psu, a.salinity_psu.mean, 1e-6);
  EXPECT_NEAR(wiz.state().next_water->depth_m, a.depth_m.mean, 1e-6);
  EXPECT_GE(find<NumberInput>(wiz, "next_deepest")->value(), a.depth_m.mean);
  EXPECT_TRUE(find<QCheckBox>(wiz, "optional_pieces")->isVisible());  // HUGIN has the 0.5 kg piece
  EXPECT_TRUE(find<QLabel>(wiz, "temperature_stale")->text().isEmpty());

  find<QRadioButton>(wiz, "water_operator")->setChecked(true);
  EXPECT_TRUE(find<NumberInput>(wiz, "next_temperature")->isEnabled());
  find<NumberInput>(wiz, "next_temperature")->setValue(nextWater().temperature_degC);
  find<NumberInput>(wiz, "next_salinity")->setValue(nextWater().salinity_psu);
  find<NumberInput>(wiz, "next_depth")->setValue(nextWater().depth_m);
  find<NumberInput>(wiz, "next_latitude")->setValue(nextWater().latitude_deg);
  find<NumberInput>(wiz, "next_deepest")->setValue(kDeepest);
  shot(wiz, "50_pre_mission");
  const PreMissionPlan oracle = oraclePlan(*wiz.state().vehicle);
  // The preview shows the same prediction.
  const QString preview = find<QLabel>(wiz, "plan_preview")->text();
  EXPECT_NE(preview.indexOf(QString("%1 ± %2 kg").arg(fixed(oracle.predicted.net_buoyancy_kg, 2).prepend(
                                                          oracle.predicted.net_buoyancy_kg > 0 ? "+" : ""),
                                                      fixed(oracle.net_sigma_kg, 2))),
            -1)
      << preview.toStdString();

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kAdjustment);
  ASSERT_TRUE(wiz.state().plan.has_value());
  const PreMissionPlan& plan = *wiz.state().plan;
  EXPECT_EQ(plan.delta, oracle.delta);
  // Displayed predicted net buoyancy = the oracle's, within the rounding shown.
  auto* table = find<QTableWidget>(wiz, "prediction");
  EXPECT_NEAR(leadingNumber(table->item(0, 2)->text()), oracle.predicted.net_buoyancy_kg, 0.005 + 1e-9);
  EXPECT_NEAR(leadingNumber(table->item(1, 2)->text()), oracle.predicted.pitch_deg, 0.005 + 1e-9);
  // The analysed log has a cruise speed and HUGIN's profile has hydrodynamics:
  // the pitch flown level is predicted too (the band the spec means).
  ASSERT_EQ(table->rowCount(), 4);
  ASSERT_TRUE(oracle.flight_pitch_after_deg.has_value());
  EXPECT_TRUE(table->item(2, 0)->text().startsWith("Pitch in flight (2.0 m/s)")) << table->item(2, 0)->text().toStdString();
  EXPECT_NEAR(leadingNumber(table->item(2, 2)->text()), *oracle.flight_pitch_after_deg, 0.005 + 1e-9);
  EXPECT_EQ(table->item(2, 4)->text(), *oracle.flight_pitch_in_band ? "✓" : "✗");
  EXPECT_NEAR(leadingNumber(table->item(3, 2)->text()), oracle.predicted.roll_deg, 0.005 + 1e-9);
  EXPECT_NEAR(leadingNumber(table->item(0, 1)->text()), oracle.net_before_kg, 0.005 + 1e-9);
  EXPECT_EQ(table->item(0, 4)->text(), oracle.buoyancy_in_band ? "✓" : "✗");
  EXPECT_GT(oracle.predicted.net_buoyancy_kg, 0.0);  // never heavy
  // Map: green and red squares = the plan's delta, piece by piece.
  int add = 0, remove = 0, changed_pairs = 0;
  for (const auto& row : oracle.delta) {
    for (int n : row) {
      add += n > 0 ? n : 0;
      remove += n < 0 ? -n : 0;
      changed_pairs += n != 0 ? 1 : 0;
    }
  }
  auto* map = find<WeightMapWidget>(*wiz.currentPage(), "weight_map");
  EXPECT_EQ(map->model().piecesToAdd(), add);
  EXPECT_EQ(map->model().piecesToRemove(), remove);
  EXPECT_GT(add + remove, 0);
  // The checklist: one step per changed (point, size) pair, nothing ticked yet.
  auto* list = find<QListWidget>(wiz, "checklist");
  ASSERT_EQ(list->count(), changed_pairs);
  for (int i = 0; i < list->count(); ++i) EXPECT_EQ(list->item(i)->checkState(), Qt::Unchecked);
  EXPECT_TRUE(list->item(0)->text().startsWith(remove > 0 ? "Remove " : "Add ")) << list->item(0)->text().toStdString();
  EXPECT_EQ(find<QLabel>(wiz, "checklist_progress")->text(), QString("0 of %1 done").arg(changed_pairs));
  const QImage before_ticks = shot(wiz, "51_adjustment");
  EXPECT_GT(auv::testing::colourFraction(before_ticks, QColor(46, 160, 67), 10), 0.0);

  for (int i = 0; i < list->count(); ++i) list->item(i)->setCheckState(Qt::Checked);
  EXPECT_EQ(find<QLabel>(wiz, "checklist_progress")->text(), QString("%1 of %1 done").arg(changed_pairs));
  EXPECT_EQ(wiz.state().checklist_done, std::vector<bool>(static_cast<std::size_t>(changed_pairs), true));
  shot(wiz, "51b_adjustment_ticked");

  // Actually installed: defaults to the plan; one more 1.2 kg piece aft/starboard.
  const std::vector<double> planned = installedAfterPlan(exampleInstalledKg(), oracle);
  auto* as = find<NumberInput>(wiz, "actual_2");
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(find<NumberInput>(wiz, QString("actual_%1").arg(i).toLatin1().constData())->value(), planned[i], 1e-9);
  }
  EXPECT_EQ(find<QLabel>(wiz, "actual_prediction")->text(), "As planned: the prediction above holds.");
  as->setValue(planned[2] + 1.2);
  std::vector<double> edited = planned;
  edited[2] += 1.2;
  EXPECT_EQ(wiz.state().actually_installed_kg, edited);
  const InstalledPrediction re = predictInstalled(*wiz.state().vehicle, oracle, exampleInstalledKg(), edited);
  const QString re_text = find<QLabel>(wiz, "actual_prediction")->text();
  EXPECT_NE(re_text.indexOf("Differs from the plan at Aft / starboard"), -1) << re_text.toStdString();
  EXPECT_NEAR(leadingNumber(re_text.mid(re_text.indexOf("net buoyancy"))), re.net_buoyancy_kg, 0.005 + 1e-9);
  // Conservation: one more 1.2 kg piece is 1.2 kg less net buoyancy.
  EXPECT_NEAR(re.net_buoyancy_kg, oracle.predicted.net_buoyancy_kg - 1.2, 1e-9);
  shot(wiz, "51c_adjustment_edited");

  // Undo (Ctrl+Z) restores the planned value, redo (Ctrl+Shift+Z) the edit.
  auto* page = qobject_cast<AdjustmentPage*>(wiz.currentPage());
  ASSERT_NE(page, nullptr);
  EXPECT_EQ(page->undoStack()->count(), 1);
  wiz.activateWindow();
  as->setFocus();
  QApplication::processEvents();
  QTest::keyClick(as, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_NEAR(as->value(), planned[2], 1e-9);
  EXPECT_NEAR(wiz.state().actually_installed_kg[2], planned[2], 1e-9);
  EXPECT_EQ(find<QLabel>(wiz, "actual_prediction")->text(), "As planned: the prediction above holds.");
  QTest::keyClick(as, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_NEAR(as->value(), planned[2] + 1.2, 1e-9);
  EXPECT_EQ(wiz.state().actually_installed_kg, edited);

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kSummary);
  shot(wiz, "52_summary");
  const QString summary = find<QLabel>(*wiz.currentPage(), "save_summary")->text();
  EXPECT_NE(summary.indexOf("different from the plan"), -1) << summary.toStdString();
  EXPECT_NE(summary.indexOf(QString("%1 of %1 steps ticked").arg(changed_pairs)), -1);

  // Exports, by path (no dialogs).
  auto* sp = qobject_cast<SummaryPage*>(wiz.currentPage());
  ASSERT_NE(sp, nullptr);
  const QString pdf = path("work_order.pdf");
  EXPECT_EQ(sp->exportPdf(pdf), "");
  QFile f(pdf);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QByteArray bytes = f.readAll();
  EXPECT_TRUE(bytes.startsWith("%PDF"));
  EXPECT_GT(bytes.size(), 1024);
  EXPECT_EQ(QString::fromLatin1(bytes).count(QRegularExpression(R"(/Type\s*/Page[^s])")), 1);  // one page
  const QString json = path("plan.json");
  EXPECT_EQ(sp->exportJson(json), "");
  const nlohmann::json j = JsonReader::parseFile(json.toStdString());
  EXPECT_EQ(j["config"], "01-02-03");
  EXPECT_TRUE(j["installed"]["differs_from_plan"].get<bool>());
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(j["installed"]["points"][i]["actual_kg"].get<double>(), edited[i], 1e-9);
    EXPECT_NEAR(j["installed"]["points"][i]["planned_kg"].get<double>(), planned[i], 1e-9);
    EXPECT_NEAR(j["recommendation"]["points"][i]["add_kg"].get<double>(), oracle.points[i].add_kg, 1e-6);
  }
  EXPECT_NEAR(j["installed"]["predicted"]["net_buoyancy_kg"].get<double>(), re.net_buoyancy_kg, 1e-9);

  // Finish: one transaction; reopening the history shows what was installed.
  wiz.button(QWizard::FinishButton)->click();
  EXPECT_EQ(find<QLabel>(*wiz.currentPage(), "save_status")->text(), "");
  HistoryStore store(path("history.sqlite").toStdString());
  const auto inst = store.latestInstalled("01-02-03", fixedNow());
  ASSERT_TRUE(inst.has_value());
  ASSERT_EQ(inst->points.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(inst->points[i].name, wiz.state().vehicle->points[i].name);
    EXPECT_NEAR(inst->points[i].mass_kg, edited[i], 1e-9);
    double pieces = 0;
    for (double p : inst->points[i].pieces_kg) pieces += p;
    EXPECT_NEAR(pieces, edited[i], 1e-9);  // the kit pieces make up the mass
  }
  ASSERT_TRUE(inst->recommendation_id.has_value());
  const auto events = store.history("01-02-03");
  ASSERT_GE(events.size(), 3u);
  const auto& rec = std::get<Recommendation>(events[events.size() - 2].record);
  EXPECT_TRUE(rec.accepted);
  EXPECT_EQ(rec.policy, "exact");
  EXPECT_EQ(rec.id, *inst->recommendation_id);
  const auto water = store.latestWater("01-02-03", fixedNow(), true);
  ASSERT_TRUE(water.has_value());
  EXPECT_DOUBLE_EQ(*water->temperature_degC, 6.0);
  EXPECT_EQ(water->source, "operator");
  EXPECT_EQ(water->measured_at, fixedNow());
}

TEST_F(PreMissionPages, WorkOrderDrawsTheExpectedStringsOnOnePage) {
  OperatorWizard wiz(sessionWithAnalysis());
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  toPreMissionWithWater(wiz);
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kAdjustment);
  const PreMissionPlan oracle = oraclePlan(*wiz.state().vehicle);
  const std::vector<double> planned = installedAfterPlan(exampleInstalledKg(), oracle);
  HistoryStore* store = wiz.history();
  const PlanBasis basis = planBasis(wiz.state(), store, fixedNow(), PlanPolicy::Exact);
  EXPECT_EQ(basis.installed_kg, exampleInstalledKg());
  const WorkOrder order = makeWorkOrder(wiz.state(), basis, fixedNow());

  // Render check: the strings that reach the paint engine.
  auv::testing::TextRecorder rec(QSize(794, 1123), 96);
  {
    QPainter p(&rec);
    drawWorkOrder(p, rec, order);
  }
  const QString drawn = rec.joined();
  for (const QString& s : {QString("Ballast work order"), QString("HUGIN 1000"), QString("01-02-03"),
                           QString("2026-05-20 12:00:00 UTC"), QString("Fore / starboard"), QString("Aft / port"),
                           QString("Operating depth 80 m"), QString("Where (top view, bow to the right)"),
                           QString("Signature")}) {
    EXPECT_NE(drawn.indexOf(s), -1) << s.toStdString() << "\n" << drawn.toStdString();
  }
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NE(drawn.indexOf(massText(planned[i], false)), -1) << i;
    EXPECT_NE(drawn.indexOf(massText(oracle.points[i].add_kg, false, true)), -1) << i;
    // The top-down map's label of the point: "<point>: <change> (<now> → <after>)".
    const QString label = QString("%1: %2 (%3 → %4)")
                              .arg(QString::fromStdString(wiz.state().vehicle->points[i].label),
                                   massText(oracle.points[i].add_kg, false, true))
                              .arg(exampleInstalledKg()[i], 0, 'f', 1)
                              .arg(planned[i], 0, 'f', 1);
    EXPECT_NE(drawn.indexOf(label), -1) << label.toStdString();
  }
  const QString net = QString("Net buoyancy %1%2 ± %3 kg")
                          .arg(oracle.predicted.net_buoyancy_kg > 0 ? "+" : "")
                          .arg(fixed(oracle.predicted.net_buoyancy_kg, 2), fixed(oracle.net_sigma_kg, 2));
  EXPECT_NE(drawn.indexOf(net), -1) << net.toStdString();
  const QString flight = QString("Pitch in flight at 2.0 m/s %1%2°")
                             .arg(*oracle.flight_pitch_after_deg > 0 ? "+" : "")
                             .arg(fixed(*oracle.flight_pitch_after_deg, 2));
  EXPECT_NE(drawn.indexOf(flight), -1) << flight.toStdString() << "\n" << drawn.toStdString();

  // The same page as an image (golden) and as a PDF.
  const QImage img = renderWorkOrder(order, 96);
  EXPECT_EQ(img.size(), QSize(794, 1123));
  img.save(QString(AUV_SCREENSHOT_DIR) + "/53_work_order.png");
  const QString problem = auv::testing::checkGolden(img, "53_work_order");
  EXPECT_TRUE(problem.isEmpty()) << problem.toStdString();
  EXPECT_GT(auv::testing::colourFraction(img, Qt::white, 5), 0.8);
  const QString pdf = path("order.pdf");
  EXPECT_EQ(writeWorkOrderPdf(order, pdf), "");
  EXPECT_GT(QFile(pdf).size(), 1024);
  EXPECT_NE(writeWorkOrderPdf(order, path("no/such/folder/order.pdf")), "");
}

TEST_F(PreMissionPages, HistoryAnalysisOlderThanAMonthAsksForANewTemperature) {
  {
    HistoryStore store(path("history.sqlite").toStdString());
    seedDemoHistory(store, AUV_RESOURCE_DIR, fixedNow() - std::chrono::days(80));
    AnalysisResult ar;
    ar.at = fixedNow() - std::chrono::days(45);  // the mission's CTD: older than one month
    ar.result = analysis::toJson(exampleHuginAnalysis());
    store.addAnalysisResult("01-02-03", ar);
    InstalledState st;
    st.installed_at = fixedNow() - std::chrono::days(46);
    const char* names[4] = {"fore_starboard", "fore_port", "aft_starboard", "aft_port"};
    for (std::size_t i = 0; i < 4; ++i) st.points.push_back({names[i], exampleInstalledKg()[i], {}});
    store.addInstalledState("01-02-03", st);
  }
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  auto* table = find<QTableWidget>(wiz, "configurations");
  auto* pre = find<QRadioButton>(wiz, "mode_pre");
  EXPECT_FALSE(pre->isEnabled());  // a new configuration has nothing to plan from
  table->selectRow(1);
  ASSERT_TRUE(pre->isEnabled());  // its history has an analysis
  pre->setChecked(true);
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kPreMission);
  EXPECT_NE(find<QLabel>(wiz, "estimate_source")->text().indexOf("history analysis #"), -1);
  EXPECT_NE(find<QLabel>(wiz, "estimate_source")->text().indexOf("(45 days ago)"), -1)
      << find<QLabel>(wiz, "estimate_source")->text().toStdString();
  EXPECT_NE(find<QLabel>(wiz, "installed_now")->text().indexOf("Aft / port 25.2 kg"), -1);
  // Thesis §5.5.3: the old temperature is neither offered nor accepted.
  EXPECT_FALSE(find<QRadioButton>(wiz, "water_ctd")->isEnabled());
  EXPECT_TRUE(find<QRadioButton>(wiz, "water_operator")->isChecked());
  EXPECT_NE(find<QLabel>(wiz, "temperature_stale")->text().indexOf("older than one month"), -1);
  auto* t = find<NumberInput>(wiz, "next_temperature");
  EXPECT_EQ(t->text(), "");  // empty, with the hint greyed in it
  EXPECT_EQ(t->lineEdit()->placeholderText(), "enter °C");
  EXPECT_FALSE(wiz.currentPage()->isComplete());
  EXPECT_FALSE(wiz.button(QWizard::NextButton)->isEnabled());
  shot(wiz, "50b_pre_mission_stale");
  t->setValue(5.5);
  EXPECT_TRUE(wiz.currentPage()->isComplete());
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kAdjustment);
  EXPECT_DOUBLE_EQ(wiz.state().plan->at_points.front().water.temperature_degC, 5.5);
}

TEST_F(PreMissionPages, KeyboardOnlyThroughTheSequence) {
  OperatorWizard wiz(sessionWithAnalysis());
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  wiz.activateWindow();
  QApplication::processEvents();
  auto focus = [&] { return QApplication::focusWidget() ? QApplication::focusWidget() : wiz.currentPage(); };
  // Start (pre mission chosen) -> vehicle -> pre mission: Enter on each.
  QTest::keyClick(focus(), Qt::Key_Return);
  QTest::keyClick(focus(), Qt::Key_Return);
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kPreMission);
  // Alt+A moves to the half-way policy, Space selects it; Alt+V and Space
  // the operator's water; Alt+T to the temperature.
  QTest::keyClick(focus(), Qt::Key_A, Qt::AltModifier);
  ASSERT_EQ(QApplication::focusWidget(), find<QRadioButton>(wiz, "policy_half"));
  QTest::keyClick(focus(), Qt::Key_Space);
  EXPECT_TRUE(find<QRadioButton>(wiz, "policy_half")->isChecked());
  QTest::keyClick(focus(), Qt::Key_V, Qt::AltModifier);
  ASSERT_EQ(QApplication::focusWidget(), find<QRadioButton>(wiz, "water_operator"));
  QTest::keyClick(focus(), Qt::Key_Space);
  EXPECT_TRUE(find<QRadioButton>(wiz, "water_operator")->isChecked());
  QTest::keyClick(focus(), Qt::Key_T, Qt::AltModifier);
  auto* t = find<NumberInput>(wiz, "next_temperature");
  ASSERT_EQ(QApplication::focusWidget(), t->lineEdit());
  // The field selected its text on focus-in: typing replaces it.
  QTest::keyClicks(focus(), "6.5");
  EXPECT_EQ(t->text(), "6.5");
  QTest::keyClick(focus(), Qt::Key_Return);
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kAdjustment);
  EXPECT_EQ(wiz.state().policy, PlanPolicy::HalfWay);
  EXPECT_DOUBLE_EQ(wiz.state().next_water->temperature_degC, 6.5);
  // Alt+S to the checklist, Space ticks each step, Down to the next.
  QTest::keyClick(focus(), Qt::Key_S, Qt::AltModifier);
  auto* list = find<QListWidget>(wiz, "checklist");
  ASSERT_EQ(QApplication::focusWidget(), list);
  ASSERT_GT(list->count(), 0);
  list->setCurrentRow(0);
  for (int i = 0; i < list->count(); ++i) {
    QTest::keyClick(list, Qt::Key_Space);
    QTest::keyClick(list, Qt::Key_Down);
  }
  for (int i = 0; i < list->count(); ++i) EXPECT_EQ(list->item(i)->checkState(), Qt::Checked) << i;
  // Enter: summary; Enter: Finish saves.
  QTest::keyClick(focus(), Qt::Key_Return);
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kSummary);
  QTest::keyClick(focus(), Qt::Key_Return);
  EXPECT_EQ(wiz.result(), QDialog::Accepted);
  HistoryStore store(path("history.sqlite").toStdString());
  const auto inst = store.latestInstalled("01-02-03", fixedNow());
  ASSERT_TRUE(inst.has_value());
  EXPECT_NE(inst->note.find("half"), std::string::npos) << inst->note;
}

TEST_F(PreMissionPages, ResumeKeepsWaterPolicyTicksAndInstalledMasses) {
  OperatorWizard wiz(sessionWithAnalysis());
  wiz.setClock(fixedNow);
  wiz.show();
  toPreMissionWithWater(wiz);
  find<QRadioButton>(wiz, "policy_half")->setChecked(true);
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kAdjustment);
  auto* list = find<QListWidget>(wiz, "checklist");
  ASSERT_GT(list->count(), 0);
  list->item(0)->setCheckState(Qt::Checked);
  auto* a0 = find<NumberInput>(wiz, "actual_0");
  a0->setValue(a0->value() + 2.4);
  const std::vector<double> installed = wiz.state().actually_installed_kg;
  const nlohmann::json j = sessionToJson(wiz.state(), wiz.currentId(), "2026-05-20T12:00:00Z");
  SavedSession saved = sessionFromJson(j.dump(), "session.json", AUV_RESOURCE_DIR);
  EXPECT_EQ(saved.state.mode, SessionMode::kPreMission);
  EXPECT_EQ(saved.state.policy, PlanPolicy::HalfWay);
  EXPECT_EQ(saved.state.next_water_source, "operator");
  EXPECT_DOUBLE_EQ(saved.state.next_deepest_m, kDeepest);
  EXPECT_EQ(saved.state.actually_installed_kg, installed);
  EXPECT_TRUE(saved.state.checklist_done.at(0));
  // The analysis is the post-mission pages' to restore; here it is given again.
  saved.state.analysis = exampleHuginAnalysis();
  saved.state.mission_installed_kg = exampleInstalledKg();
  OperatorWizard again(makeEmptyState(AUV_RESOURCE_DIR));
  again.setClock(fixedNow);
  again.show();
  ASSERT_TRUE(again.resume(saved));
  ASSERT_EQ(again.currentId(), OperatorWizard::kAdjustment);
  EXPECT_NEAR(find<NumberInput>(again, "actual_0")->value(), installed[0], 1e-9);
  EXPECT_EQ(find<QListWidget>(again, "checklist")->item(0)->checkState(), Qt::Checked);
}

// Issue 14, items 1 and 6: every numeric field of the pre-mission and
// adjustment pages typed key by key; the deepest depth is never above the
// operating depth (default: the operating depth without a log), and a
// shallower one typed is refused naming the field.
TEST_F(PreMissionPages, TypedFieldsAndDeepestDepthNeverAboveTheOperatingDepth) {
  OperatorWizard wiz(sessionWithAnalysis());
  wiz.setClock(fixedNow);
  wiz.show();
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kPreMission);
  QTest::mouseClick(find<QRadioButton>(wiz, "water_operator"), Qt::LeftButton);
  ASSERT_TRUE(find<QRadioButton>(wiz, "water_operator")->isChecked());
  auto* depth = find<NumberInput>(wiz, "next_depth");
  auto* deepest = find<NumberInput>(wiz, "next_deepest");
  EXPECT_GE(deepest->value(), depth->value());
  EXPECT_GT(deepest->value(), 0.0);
  EXPECT_GE(auv::testing::typeIntoEveryNumberField(wiz.currentPage()), 5);
  auv::testing::typeInto(find<NumberInput>(wiz, "next_temperature"), "6.5");
  auv::testing::typeInto(find<NumberInput>(wiz, "next_latitude"), "59.4");
  auv::testing::typeInto(depth, "200");
  auv::testing::typeInto(deepest, "150");
  wiz.next();
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kPreMission);
  const QString err = find<QLabel>(*wiz.currentPage(), "error")->text();
  EXPECT_NE(err.indexOf("Deepest depth"), -1) << err.toStdString();
  auv::testing::typeInto(deepest, "374");
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kAdjustment);
  EXPECT_DOUBLE_EQ(wiz.state().next_deepest_m, 374.0);
  EXPECT_GE(auv::testing::typeIntoEveryNumberField(wiz.currentPage()), 4);
}

}  // namespace auv::ui
