// The whole thesis sequence in the GUI on the bundled data, one history
// throughout (issue #7, "done when"): first mission (crane weighing) ->
// post mission (the simulated survey log: import, analysis, model check) ->
// pre mission (plan, adjust, confirm what was installed, save) -> the next
// session's start page shows what was actually installed.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include "widgets/number_input.h"
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QRadioButton>
#include <QTableWidget>
#include <cmath>
#include <functional>

#include "history/store.h"
#include "pages/log_import_page.h"
#include "pages/model_check_page.h"
#include "planning/installed_prediction.h"
#include "screenshot.h"
#include "ui_fixture.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"
#include "wizard/pre_mission_inputs.h"

using namespace auv;
using namespace auv::ui;
using auv::testing::find;
using auv::testing::shot;

namespace {

// The cap only stops a hung test. The whole sequence takes about 5 s alone
// and 50 s under the parallel ctest (it took 150-270 s before the workers
// cleared the upper AVX state, docs/decisions/worker-avx-state.md).
void waitWhile(const std::function<bool()>& busy) {
  QElapsedTimer t;
  t.start();
  while (busy() && t.elapsed() < 900000) QApplication::processEvents(QEventLoop::AllEvents, 20);
  QApplication::processEvents();
}

int rowOf(QTableWidget* t, const QString& id) {
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, 0) && t->item(r, 0)->text() == id) return r;
  return -1;
}

}  // namespace

class ThesisSequence : public auv::testing::UiTest {};

TEST_F(ThesisSequence, FirstThenPostThenPreMissionOnTheBundledData) {
  const QString log = path("survey.csv");
  writeDemoSurveyLog(AUV_RESOURCE_DIR, log.toStdString());

  // 1. First mission: weigh, compute, Finish saves the configuration.
  {
    OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
    wiz.setClock(fixedNow);
    wiz.setAutosaveEnabled(false);
    wiz.resize(1000, 760);
    wiz.show();
    for (int i = 0; i < 4; ++i) wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
    ASSERT_TRUE(wiz.state().report.has_value());
    wiz.button(QWizard::FinishButton)->click();
    ASSERT_EQ(wiz.result(), QDialog::Accepted);
  }

  // 2. Post mission on the same configuration, then straight on to plan the next one.
  std::vector<double> installed_after;
  {
    OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
    wiz.setClock([] { return fixedNow() + std::chrono::hours(24); });
    wiz.setAutosaveEnabled(false);
    wiz.resize(1000, 760);
    wiz.show();
    auto* table = find<QTableWidget>(wiz, "configurations");
    const int row = rowOf(table, "01-02-03");
    ASSERT_GE(row, 0);
    table->selectRow(row);
    auto* post = find<QRadioButton>(wiz, "mode_post");
    ASSERT_TRUE(post->isEnabled());
    post->setChecked(true);
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kLogImport);
    auto* import = qobject_cast<LogImportPage*>(wiz.currentPage());
    import->startImport(log);
    waitWhile([import] { return import->job().running(); });
    ASSERT_TRUE(wiz.state().log) << "import failed";
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kDeviationPlots);
    ASSERT_TRUE(wiz.state().analysis.has_value());
    EXPECT_TRUE(wiz.state().analysis->net_buoyancy_kg.known) << wiz.state().analysis->net_buoyancy_kg.why_not;
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kModelCheck);
    auto* check = qobject_cast<ModelCheckPage*>(wiz.currentPage());
    waitWhile([check] { return check->job().running(); });
    ASSERT_FALSE(check->job().running()) << "the model check did not finish within the cap";
    // The demo survey is our own model flown with noise and conceals
    // nothing: checked with its analysis's calibration held, the check names
    // no term, so the plan keeps the analysis's estimate and the page has no
    // difference to explain.
    ASSERT_TRUE(check->outcome().result.has_value());
    EXPECT_TRUE(check->outcome().result->missing_physics.empty()) << check->outcome().result->missing_physics.front().id;
    const auto e = sessionEstimate(wiz.state());
    ASSERT_TRUE(e.has_value());
    EXPECT_EQ(e->source, discrepancy::EstimateSource::kAnalysis);
    EXPECT_DOUBLE_EQ(e->report.net_buoyancy_kg.value, wiz.state().analysis->net_buoyancy_kg.value);
    EXPECT_EQ(find<QLabel>(wiz, "check_summary")->text().indexOf("differ by"), -1);
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kPreMission);
    find<QRadioButton>(wiz, "water_operator")->setChecked(true);
    find<NumberInput>(wiz, "next_temperature")->setValue(7.0);
    find<NumberInput>(wiz, "next_salinity")->setValue(34.5);
    find<NumberInput>(wiz, "next_depth")->setValue(60.0);
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kAdjustment);
    ASSERT_TRUE(wiz.state().plan.has_value());
    const PreMissionPlan& plan = *wiz.state().plan;
    // Nothing was installed after the first mission, so nothing can come
    // out: the plan may fall short of the margin, but never negative.
    for (const auto& pt : plan.at_points) EXPECT_GE(pt.net_after_kg, 0.0) << pt.role;
    // The technician ticks every step but ends with one piece more at aft / port.
    const std::size_t n = plan.points.size();
    ASSERT_EQ(wiz.state().actually_installed_kg.size(), n);
    installed_after = wiz.state().actually_installed_kg;
    auto* list = find<QListWidget>(wiz, "checklist");
    for (int i = 0; i < list->count(); ++i) list->item(i)->setCheckState(Qt::Checked);
    installed_after[3] += 1.2;  // one 1.2 kg piece more than planned at aft / port
    find<NumberInput>(wiz, "actual_3")->setValue(installed_after[3]);
    EXPECT_EQ(wiz.state().actually_installed_kg, installed_after);
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kSummary);
    shot(wiz, "60_thesis_sequence_summary");
    wiz.button(QWizard::FinishButton)->click();
    ASSERT_EQ(wiz.result(), QDialog::Accepted);
  }

  // 3. The history has the whole sequence, and the next session starts
  //    from what was actually installed.
  HistoryStore store(path("history.sqlite").toStdString());
  int weighings = 0, missions = 0, recommendations = 0, installed = 0;
  for (const auto& e : store.history("01-02-03")) {
    weighings += e.kind == EventKind::kWeighing;
    missions += e.kind == EventKind::kMission;
    recommendations += e.kind == EventKind::kRecommendation;
    installed += e.kind == EventKind::kInstalled;
  }
  EXPECT_EQ(weighings, 1);
  EXPECT_EQ(missions, 1);
  EXPECT_EQ(recommendations, 2);  // first mission's and the pre-mission plan
  EXPECT_EQ(store.latestAnalysis("01-02-03", fixedNow() + std::chrono::hours(48))->mission_id.has_value(), true);
  EXPECT_GE(installed, 1);
  const auto last = store.latestInstalled("01-02-03", fixedNow() + std::chrono::hours(48));
  ASSERT_TRUE(last);
  ASSERT_EQ(last->points.size(), installed_after.size());
  for (std::size_t i = 0; i < installed_after.size(); ++i) EXPECT_NEAR(last->points[i].mass_kg, installed_after[i], 1e-9) << i;

  OperatorWizard next(makeEmptyState(AUV_RESOURCE_DIR));
  next.setClock([] { return fixedNow() + std::chrono::hours(48); });
  next.setAutosaveEnabled(false);
  next.resize(1000, 760);
  next.show();
  auto* table = find<QTableWidget>(next, "configurations");
  table->selectRow(rowOf(table, "01-02-03"));
  EXPECT_TRUE(find<QRadioButton>(next, "mode_pre")->isEnabled());  // an analysis is in the history
  const QString st = find<QLabel>(next, "last_state")->text();
  EXPECT_NE(st.indexOf(QString("Aft / port %1 kg").arg(installed_after[3], 0, 'f', 1)), -1) << st.toStdString();
}
