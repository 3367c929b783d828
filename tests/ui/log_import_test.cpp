// The mission-log import page: format by content, worker thread with
// progress and Cancel, and the summary of what was read and skipped.
#include <gtest/gtest.h>

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QTableWidget>
#include <QTextStream>
#include <QUrl>
#include <cstdio>

#include "history/store.h"
#include "pages/log_import_page.h"
#include "pages/model_check_page.h"
#include "screenshot.h"
#include "synthetic_log.h"
#include "ui_fixture.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
using auv::testing::find;
using auv::testing::shot;

class LogImport : public auv::testing::UiTest {
 protected:
  // Waits for the import without blocking the event loop (as the UI does).
  static void waitForImport(LogImportPage* page, int timeout_ms = 20000) {
    QElapsedTimer t;
    t.start();
    while (page->job().running() && t.elapsed() < timeout_ms) QApplication::processEvents(QEventLoop::AllEvents, 20);
    QApplication::processEvents();
  }
  // From the plots page on through the model check (waiting for it) to the
  // page that finishes the post-mission sequence, then Finish. Returns that
  // page's id (the mission is saved there).
  static int finishPostMission(OperatorWizard& wiz) {
    while (wiz.nextId() != -1) {
      const int before = wiz.currentId();
      wiz.next();
      if (wiz.currentId() == before) break;
      if (auto* check = qobject_cast<ModelCheckPage*>(wiz.currentPage())) {
        QElapsedTimer t;
        t.start();
        while (check->job().running() && t.elapsed() < 60000) QApplication::processEvents(QEventLoop::AllEvents, 20);
        QApplication::processEvents();
      }
    }
    const int last = wiz.currentId();
    wiz.button(QWizard::FinishButton)->click();
    return last;
  }
  // A post-mission session on a configuration already in the history.
  std::unique_ptr<OperatorWizard> postWizard(const QString& log) {
    {
      HistoryStore store(path("history.sqlite").toStdString());
      if (!store.configuration("01-02-03")) seedDemoHistory(store, AUV_RESOURCE_DIR, makeUtc(2026, 4, 30, 9, 0, 0));
    }
    WizardState s = makeDemoState(AUV_RESOURCE_DIR);
    s.configuration_in_history = true;
    s.mode = SessionMode::kPostMission;
    auto wiz = std::make_unique<OperatorWizard>(s);
    wiz->setClock(fixedNow);
    wiz->setAutosaveEnabled(false);
    wiz->resize(1000, 760);
    wiz->show();
    wiz->next();
    wiz->next();
    EXPECT_EQ(wiz->currentId(), OperatorWizard::kLogImport);
    if (!log.isEmpty()) {
      auto* page = qobject_cast<LogImportPage*>(wiz->currentPage());
      page->startImport(log);
      waitForImport(page);
    }
    return wiz;
  }
};

TEST_F(LogImport, ReadsTheSurveyAndSavesTheMission) {
  const QString log = path("survey.csv");
  const std::size_t rows = auv::testing::writeSyntheticSurvey(log.toStdString());
  auto wiz = postWizard(log);
  ASSERT_NE(wiz->state().log, nullptr) << find<QLabel>(*wiz, "import_status")->text().toStdString();
  EXPECT_EQ(wiz->state().log->rowCount(), rows);
  EXPECT_EQ(wiz->state().log_format, "mission-log CSV v1");
  EXPECT_EQ(find<QProgressBar>(*wiz, "progress")->value(), 100);
  const QString summary = find<QLabel>(*wiz, "import_summary")->text();
  EXPECT_NE(summary.indexOf(QString("<b>%1 rows</b>").arg(rows)), -1) << summary.toStdString();
  EXPECT_NE(summary.indexOf("<b>5 channels</b>"), -1) << summary.toStdString();
  EXPECT_NE(summary.indexOf("over 1.50 h"), -1) << summary.toStdString();
  EXPECT_NE(summary.indexOf("Skipped 0 rows"), -1);
  EXPECT_NE(summary.indexOf("commanded depth ✓"), -1);
  EXPECT_FALSE(find<QListWidget>(*wiz, "problems")->isVisible());  // no empty box when nothing went wrong
  EXPECT_TRUE(wiz->currentPage()->isComplete());
  shot(*wiz, "20_log_import");
  EXPECT_EQ(QSettings().value("paths/last_log_folder").toString(), dirPath());

  wiz->next();
  ASSERT_EQ(wiz->currentId(), OperatorWizard::kDeviationPlots);
  finishPostMission(*wiz);
  EXPECT_EQ(wiz->result(), QDialog::Accepted);
  HistoryStore store(path("history.sqlite").toStdString());
  const auto st = store.lastState("01-02-03", fixedNow());
  ASSERT_TRUE(st && st->last_mission);
  EXPECT_EQ(st->last_mission->summary["rows"].get<std::size_t>(), rows);
  EXPECT_EQ(st->last_mission->summary["rows_skipped"].get<long long>(), 0);
}

TEST_F(LogImport, SameLogTwiceIsRefusedAndNothingIsSaved) {
  const QString log = path("survey.csv");
  auv::testing::writeSyntheticSurvey(log.toStdString());
  for (int attempt = 0; attempt < 2; ++attempt) {
    auto wiz = postWizard(log);
    wiz->next();
    const int last = finishPostMission(*wiz);
    if (attempt == 0) {
      EXPECT_EQ(wiz->result(), QDialog::Accepted);
    } else {
      // The store refuses a duplicate log; the page says so and stays open.
      EXPECT_EQ(wiz->currentId(), last);
      EXPECT_NE(find<QLabel>(*wiz->currentPage(), "save_status")->text().indexOf("Not saved"), -1);
    }
  }
  HistoryStore store(path("history.sqlite").toStdString());
  int missions = 0;
  for (const auto& e : store.history("01-02-03")) missions += e.kind == EventKind::kMission;
  EXPECT_EQ(missions, 1);
}

TEST_F(LogImport, PostMissionDemoImportsItsLogOnArrival) {
  {
    HistoryStore store(path("history.sqlite").toStdString());
    seedDemoHistory(store, AUV_RESOURCE_DIR, makeUtc(2026, 4, 30, 9, 0, 0));
  }
  // What `auvballast-gui --demo post` opens: the history has the configuration,
  // the session names a log that nobody has read yet.
  OperatorWizard wiz(makePostMissionDemoState(AUV_RESOURCE_DIR, path("demo.csv").toStdString()));
  wiz.setClock(fixedNow);
  wiz.show();
  EXPECT_TRUE(find<QRadioButton>(wiz, "mode_post")->isChecked());
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kLogImport);
  waitForImport(qobject_cast<LogImportPage*>(wiz.currentPage()));
  ASSERT_NE(wiz.state().log, nullptr);
  EXPECT_TRUE(wiz.state().log->has("depth_cmd"));
  wiz.next();
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kDeviationPlots);
}

TEST_F(LogImport, DamagedRowsAreSkippedAndExplained) {
  const QString log = path("damaged.csv");
  QFile f(log);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Text));
  QTextStream out(&f);
  out << "# vehicle: hugin1000\n"
      << "time [s],depth [m],pitch [deg]\n"
      << "0,1.0,0.5\n1,1.5,abc\n2,2.0,0.7\n1.5,2.2,0.8\n3,2.5,0.9\n4,3.0\n5,3.5,1.0\n";
  f.close();
  auto wiz = postWizard(log);
  ASSERT_NE(wiz->state().log, nullptr);
  const ReadReport& r = *wiz->state().log_report;
  EXPECT_EQ(wiz->state().log->rowCount(), static_cast<std::size_t>(r.rows_kept));
  EXPECT_EQ(r.rows_skipped, 3);  // "abc", time going back, missing cell
  const QString summary = find<QLabel>(*wiz, "import_summary")->text();
  EXPECT_NE(summary.indexOf("Skipped 3 rows"), -1) << summary.toStdString();
  EXPECT_NE(summary.indexOf("rows going back in time"), -1) << summary.toStdString();
  EXPECT_NE(summary.indexOf("commanded depth ✗"), -1);
  auto* problems = find<QListWidget>(*wiz, "problems");
  ASSERT_GE(problems->count(), 3);
  EXPECT_TRUE(problems->isVisible());
  EXPECT_NE(problems->item(0)->text().indexOf("damaged.csv:4"), -1) << problems->item(0)->text().toStdString();
  shot(*wiz, "20b_log_import_damaged");
}

TEST_F(LogImport, UnreadableFileIsRefusedNextToTheField) {
  const QString log = path("picture.bin");
  QFile f(log);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  QByteArray junk;
  for (int i = 0; i < 4096; ++i) junk.append(static_cast<char>((i * 37) & 0xff));
  f.write(junk);
  f.close();
  auto wiz = postWizard(log);
  EXPECT_EQ(wiz->state().log, nullptr);
  const QString status = find<QLabel>(*wiz, "import_status")->text();
  EXPECT_NE(status.indexOf("Cannot read this file"), -1) << status.toStdString();
  EXPECT_FALSE(wiz->currentPage()->isComplete());
}

TEST_F(LogImport, DroppedFileIsImported) {
  const QString log = path("survey.csv");
  auv::testing::writeSyntheticSurvey(log.toStdString());
  auto wiz = postWizard(QString());
  auto* page = qobject_cast<LogImportPage*>(wiz->currentPage());
  QMimeData mime;
  mime.setUrls({QUrl::fromLocalFile(log)});
  QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(page, &enter);
  EXPECT_TRUE(enter.isAccepted());
  QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(page, &drop);
  waitForImport(page);
  ASSERT_NE(wiz->state().log, nullptr);
  EXPECT_EQ(find<QLineEdit>(*wiz, "log_path")->text(), log);
}

TEST_F(LogImport, CancelMidwayKeepsNothingAndTheUiStaysResponsive) {
  // ~40 MB: long enough to cancel in the middle, generated here.
  const QString log = path("big.csv");
  {
    std::FILE* f = std::fopen(log.toLocal8Bit().constData(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("# vehicle: hugin1000\ntime [s],depth [m],depth_cmd [m],pitch [deg],pitch_cmd [deg],roll [deg]\n", f);
    for (int i = 0; i < 800000; ++i) {
      std::fprintf(f, "%.1f,%.3f,50,%.3f,0,%.3f\n", i * 0.1, 50.0 + (i % 97) * 0.01, (i % 31) * 0.1 - 1.5,
                   (i % 17) * 0.05);
    }
    std::fclose(f);
  }
  auto wiz = postWizard(QString());
  auto* page = qobject_cast<LogImportPage*>(wiz->currentPage());
  page->job().setBlockBytes(64 * 1024);  // frequent progress callbacks
  auto* progress = find<QProgressBar>(*wiz, "progress");
  auto* cancel = find<QPushButton>(*wiz, "cancel_import");
  page->startImport(log);
  EXPECT_TRUE(cancel->isEnabled());
  QElapsedTimer t, step;
  t.start();
  qint64 longest_step = 0;
  while (page->job().running() && progress->value() < 5 && t.elapsed() < 20000) {
    step.start();
    QApplication::processEvents(QEventLoop::AllEvents, 10);
    longest_step = std::max(longest_step, step.elapsed());
  }
  ASSERT_TRUE(page->job().running()) << "the read finished before it could be cancelled";
  const int at = progress->value();
  EXPECT_GT(at, 0);
  EXPECT_LT(at, 100);
  cancel->click();
  while (page->job().running() && t.elapsed() < 20000) {
    step.start();
    QApplication::processEvents(QEventLoop::AllEvents, 10);
    longest_step = std::max(longest_step, step.elapsed());
  }
  QApplication::processEvents();
  // The UI thread never waited on the reader.
  EXPECT_LT(longest_step, 200);
  EXPECT_EQ(wiz->state().log, nullptr);
  EXPECT_LT(progress->value(), 100);
  const QString status = find<QLabel>(*wiz, "import_status")->text();
  EXPECT_NE(status.indexOf("Import cancelled"), -1) << status.toStdString();
  EXPECT_FALSE(wiz->currentPage()->isComplete());
  EXPECT_FALSE(cancel->isEnabled());
  // No golden: where the read stops varies from run to run.
  auv::testing::screenshot(*wiz, "20c_log_import_cancelled");
}

}  // namespace auv::ui
