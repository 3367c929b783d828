// Issue 14 item 9: an 1100 h log must not freeze the window. The analysis
// and the plot preparation run in workers with a busy indicator, Next waits
// for them, the result is the synchronous one, and the plots keep a
// readable min/max envelope that gives the details back on zoom.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QEventLoop>
#include <QtCharts/QLineSeries>
#include <QFileInfo>

#include "analysis/mission_analysis.h"
#include "event_loop_gap.h"
#include "history/store.h"
#include "long_synthetic_log.h"
#include "pages/deviation_plots_page.h"
#include "screenshot.h"
#include "ui_fixture.h"
#include "widgets/busy_indicator.h"
#include "widgets/linked_chart_view.h"
#include "wizard/background_task.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {

namespace {
bool hasPoint(const QList<QPointF>& points, double x, double y) {
  for (const QPointF& p : points)
    if (p.x() == x && p.y() == y) return true;
  return false;
}
}  // namespace

// The product's grace (ui_test_main raises it for the other tests).
class BigLog : public auv::testing::UiTest {
 protected:
  void SetUp() override {
    UiTest::SetUp();
    saved_grace_ = BackgroundTask::graceMs();
    BackgroundTask::setGraceMs(80);
  }
  void TearDown() override {
    BackgroundTask::setGraceMs(saved_grace_);
    UiTest::TearDown();
  }
  int saved_grace_ = 0;
};

TEST_F(BigLog, ElevenHundredHoursKeepTheWindowResponsiveAndTheEnvelopeReadable) {
  const std::size_t spike = 2'000'017;  // one bad pitch sample (40 deg) mid-mission
  auto log = std::make_shared<MissionLog>(auv::testing::syntheticLongSurvey(1100.0, spike));
  ASSERT_EQ(log->rowCount(), 3'960'000u);
  {
    HistoryStore store(path("history.sqlite").toStdString());
    seedDemoHistory(store, AUV_RESOURCE_DIR, makeUtc(2026, 4, 30, 9, 0, 0));
  }
  WizardState s = makeDemoState(AUV_RESOURCE_DIR);
  s.configuration_in_history = true;
  s.mode = SessionMode::kPostMission;
  s.log = log;
  s.log_file = "long.csv";
  s.log_format = "mission-log CSV v1";
  s.log_report = ReadReport{};
  OperatorWizard wiz(s);
  wiz.setClock(fixedNow);
  wiz.setAutosaveEnabled(false);
  wiz.resize(1000, 760);
  wiz.show();
  wiz.next();
  wiz.next();
  QApplication::processEvents();

  // Next to the plots page from the event loop, as a click would, with the
  // loop's longest gap measured throughout.
  DeviationPlotsPage* page = nullptr;
  bool saw_busy = false, next_enabled_while_busy = false, hidden_while_busy = false;
  QString words;
  QEventLoop loop;
  auv::testing::EventLoopGapMeter meter([&] {
    page = qobject_cast<DeviationPlotsPage*>(wiz.currentPage());
    if (!page) return;
    if (page->busy()) {
      saw_busy = true;
      hidden_while_busy = hidden_while_busy || !page->busyIndicator().isVisible();
      next_enabled_while_busy = next_enabled_while_busy || wiz.button(QWizard::NextButton)->isEnabled();
      words = page->busyIndicator().text();
    } else {
      loop.quit();
    }
  });
  QTimer::singleShot(0, &wiz, [&] { wiz.next(); });
  QTimer::singleShot(180000, &loop, [&] { loop.quit(); });
  loop.exec();
  ASSERT_NE(page, nullptr);
  ASSERT_FALSE(page->busy()) << "the analysis did not end within 3 min";
  std::printf("[ big log ] 1100 h, 3.96e6 rows: longest event-loop gap %.0f ms over %d ticks\n", meter.worstGapMs(),
              meter.ticks());
  // Measured 150-290 ms with the machine at load 10 on 2 cores (the grace,
  // then applying each result and the first paint of 3667 segments), against
  // ~4.3 s with the work on the UI thread (bench/ui_freeze_bench); the bound
  // leaves a loaded CI runner some slack.
  EXPECT_LT(meter.worstGapMs(), 400.0);
  EXPECT_TRUE(saw_busy);
  EXPECT_FALSE(hidden_while_busy);
  EXPECT_FALSE(next_enabled_while_busy);
  EXPECT_FALSE(words.isEmpty());
  EXPECT_FALSE(page->busyIndicator().isVisible());
  EXPECT_TRUE(wiz.button(QWizard::NextButton)->isEnabled());

  // The same analysis as on the UI thread.
  ASSERT_TRUE(wiz.state().analysis.has_value()) << page->analysisError().toStdString();
  analysis::AnalysisOptions o;
  o.log_name = "long.csv";
  if (wiz.state().mission_installed_kg.size() == wiz.state().vehicle->points.size())
    o.installed_kg = wiz.state().mission_installed_kg;
  const analysis::AnalysisReport sync = analysis::analyzeMission(*log, *wiz.state().vehicle, o);
  EXPECT_EQ(toJson(*wiz.state().analysis).dump(), toJson(sync).dump());
  EXPECT_GT(page->shadedSegments(DeviationPlotsPage::kDepth), 0);

  // Whole log: every series is a band bounded by the plot width, and the
  // one-sample spike is on the pitch band's upper edge.
  using P = DeviationPlotsPage;
  EXPECT_EQ(page->samples(P::kPitch, 0), 3'960'000u);
  const double spike_min = static_cast<double>(spike) / 60.0;
  for (int plot : {P::kDepth, P::kPitch, P::kRoll}) {
    const int width = static_cast<int>(page->view(plot)->chart()->plotArea().width());
    EXPECT_GE(page->bandEdge(plot, 0, true).size(), width / 2) << plot;
    EXPECT_LE(page->pointsDrawn(plot, 0), std::max(width, 200) + 2) << plot;
    EXPECT_LE(page->bandEdge(plot, 0, true).size(), std::max(width, 200) + 2) << plot;
    EXPECT_LE(page->bandEdge(plot, 0, false).size(), std::max(width, 200) + 2) << plot;
  }
  EXPECT_TRUE(hasPoint(page->bandEdge(P::kPitch, 0, true), spike_min, 40.0));
  // No golden (the test is too slow for one), but a picture to look at.
  auv::testing::screenshot(wiz, "21e_deviation_plots_1100h");
  // Zoom on the depth chart to 10 min around it: the pitch chart follows,
  // and its raw samples, the spike among them, are back as a line.
  const auto [t0, t1] = page->fullRange();
  page->view(P::kDepth)->zoomX(10.0 / (t1 - t0), spike_min);
  EXPECT_NEAR(page->xRange(P::kPitch).second - page->xRange(P::kPitch).first, 10.0, 1e-6);
  EXPECT_TRUE(page->bandEdge(P::kPitch, 0, true).isEmpty());
  EXPECT_NEAR(page->pointsDrawn(P::kPitch, 0), 600 + 2, 2);
  EXPECT_TRUE(hasPoint(page->line(P::kPitch, 0)->points(), spike_min, 40.0));
  auv::testing::screenshot(wiz, "21f_deviation_plots_1100h_zoomed");
}

}  // namespace auv::ui
