// Issue 14 item 9: how long the wizard's window freezes when an 1100 h log
// (3.96 million rows at 1 Hz, made up in memory) reaches the analysis and
// plots page. The longest gap of a 50 ms timer on the UI event loop is the
// freeze: "before" runs the analysis and the plot preparation on the UI
// thread as the page did before, "after" in the workers. Also the cost of
// one full-view decimation of one series (every zoom/pan step): the scan of
// all samples before, the min/max pyramid after.
//   QT_QPA_PLATFORM=offscreen ./build/bench/ui_freeze_bench [hours]
#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QEventLoop>
#include <QTimer>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "event_loop_gap.h"
#include "history/store.h"
#include "long_synthetic_log.h"
#include "pages/deviation_plots_page.h"
#include "plot/envelope_decimation.h"
#include "plot/min_max_decimation.h"
#include "plot/plot_trace.h"
#include "widgets/busy_indicator.h"
#include "wizard/background_task.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace {

using namespace auv;
using namespace auv::ui;

struct Freeze {
  double worst_gap_ms = 0.0;
  double total_s = 0.0;
  int ticks = 0;
  bool busy_seen = false;
};

Freeze measure(const std::shared_ptr<const MissionLog>& log, bool inline_work) {
  BackgroundTask::setRunInlineForBench(inline_work);
  WizardState s = makeDemoState(AUV_RESOURCE_DIR);
  s.configuration_in_history = true;
  s.mode = SessionMode::kPostMission;
  s.log = log;
  s.log_file = "long.csv";
  s.log_format = "mission-log CSV v1";
  s.log_report = ReadReport{};
  OperatorWizard wiz(s);
  wiz.setAutosaveEnabled(false);
  wiz.resize(1000, 760);
  wiz.show();
  wiz.next();
  wiz.next();
  QApplication::processEvents();
  Freeze f;
  QEventLoop loop;
  bool asked = false;
  auv::testing::EventLoopGapMeter meter([&] {
    auto* page = qobject_cast<DeviationPlotsPage*>(wiz.currentPage());
    if (!page || !asked) return;
    if (page->busy()) f.busy_seen = f.busy_seen || page->busyIndicator().isVisible();
    else loop.quit();
  });
  const auto start = std::chrono::steady_clock::now();
  QTimer::singleShot(0, &wiz, [&] {
    asked = true;
    wiz.next();
  });
  QTimer::singleShot(600000, &loop, [&] { loop.quit(); });
  loop.exec();
  f.total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  f.worst_gap_ms = meter.worstGapMs();
  f.ticks = meter.ticks();
  BackgroundTask::setRunInlineForBench(false);
  return f;
}

double msOf(const std::function<void()>& f, int reps) {
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < reps; ++k) f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / reps;
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  const double hours = argc > 1 ? std::atof(argv[1]) : 1100.0;
  const QString dir = QDir::tempPath() + "/auvballast-ui-freeze-bench";
  QDir(dir).removeRecursively();
  QDir().mkpath(dir);
  qputenv("AUVBALLAST_HISTORY", (dir + "/history.sqlite").toLocal8Bit());
  qputenv("AUVBALLAST_AUTOSAVE", (dir + "/session.json").toLocal8Bit());
  QApplication app(argc, argv);
  {
    HistoryStore store((dir + "/history.sqlite").toStdString());
    seedDemoHistory(store, AUV_RESOURCE_DIR, makeUtc(2026, 4, 30, 9, 0, 0));
  }
  auto log = std::make_shared<const MissionLog>(auv::testing::syntheticLongSurvey(hours, 2'000'017));
  std::printf("log: %.0f h, %zu rows x %zu channels\n", hours, log->rowCount(), log->channels.size());

  const Freeze before = measure(log, true);
  const Freeze after = measure(log, false);
  std::printf("analysis + plots page, longest UI event-loop gap (50 ms timer):\n");
  std::printf("  before (work on the UI thread): %8.0f ms  (page ready after %.1f s, %d ticks)\n", before.worst_gap_ms,
              before.total_s, before.ticks);
  std::printf("  after  (workers, busy shown %s): %8.0f ms  (page ready after %.1f s, %d ticks)\n",
              after.busy_seen ? "yes" : "no", after.worst_gap_ms, after.total_s, after.ticks);

  const PlotTrace pitch = preparePlotTrace(*log, "pitch");
  const double t0 = pitch.t_min.front(), t1 = pitch.t_min.back();
  std::size_t points = 0;
  const double scan_ms = msOf([&] { points = decimateMinMax(pitch.t_min, pitch.v, t0, t1, 1000).size(); }, 5);
  Envelope e;
  const double pyramid_ms = msOf([&] { e = decimateEnvelope(pitch.t_min, pitch.v, pitch.pyramid, t0, t1, 1000); }, 50);
  const double prepare_ms = msOf([&] { (void)preparePlotTrace(*log, "pitch"); }, 2);
  std::printf("one series, whole log, 1000 px: scan %.2f ms (%zu points) -> pyramid %.3f ms (band %zu + %zu, mean %zu)\n",
              scan_ms, points, pyramid_ms, e.lower.size(), e.upper.size(), e.line.size());
  std::printf("plot preparation of one series in the worker (minutes + pyramid): %.0f ms\n", prepare_ms);
  return 0;
}
