// Issue 14, items 2, 3 and 8: a technician's first launch with an empty home
// folder (the history folder does not exist), Finish that says what was
// saved, Escape/Cancel that ask, autosave of what is being typed, the first
// mission's installed state, and the keyboard on every page.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QFile>
#include <QFileInfo>
#include <QGroupBox>
#include <QLabel>
#include <QTableWidget>
#include <QtTest/QTest>

#include "history/default_location.h"
#include "history/store.h"
#include "typing.h"
#include "ui_fixture.h"
#include "wizard/app_paths.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"
#include "wizard/session_json.h"

namespace auv::ui {
using auv::testing::find;
using auv::testing::focused;
using auv::testing::typeInto;

namespace {

struct Asked {
  QString title, text;
  bool question;
};

// Answers every question with `answer` and keeps what was asked.
struct Recorder {
  std::vector<Asked> asked;
  bool answer = true;
  OperatorWizard::Asker asker() {
    return [this](const QString& t, const QString& x, bool q) {
      asked.push_back({t, x, q});
      return answer;
    };
  }
};

void pressEnter(QWizard& wiz) {
  if (!focused()) QApplication::setActiveWindow(&wiz);
  QTest::keyClick(focused() ? focused() : wiz.currentPage(), Qt::Key_Return);
  QApplication::processEvents();
}

}  // namespace

class FirstLaunch : public auv::testing::UiTest {
 protected:
  void SetUp() override {
    UiTest::SetUp();
    old_home_ = qgetenv("HOME");
    old_xdg_ = qgetenv("XDG_DATA_HOME");
    // A user who never ran the program: nothing below these folders exists.
    qunsetenv("AUVBALLAST_HISTORY");
    qunsetenv("AUVBALLAST_AUTOSAVE");
    qputenv("HOME", path("home").toLocal8Bit());
    qputenv("XDG_DATA_HOME", path("xdg").toLocal8Bit());
  }
  void TearDown() override {
    qputenv("HOME", old_home_);
    if (old_xdg_.isEmpty()) qunsetenv("XDG_DATA_HOME"); else qputenv("XDG_DATA_HOME", old_xdg_);
    UiTest::TearDown();
  }
  QByteArray old_home_, old_xdg_;
};

TEST_F(FirstLaunch, OneHistoryPathForWizardAndCommandLine) {
  const QString expected = path("xdg") + "/auvballast/history.sqlite";
  EXPECT_EQ(historyFilePath(), expected);
  EXPECT_EQ(QString::fromStdString(defaultHistoryPath()), expected);  // the CLI's historyPath() uses this
  EXPECT_EQ(autosaveFilePath(), path("xdg") + "/auvballast/session.json");
  qunsetenv("XDG_DATA_HOME");
  EXPECT_EQ(historyFilePath(), path("home") + "/.local/share/auvballast/history.sqlite");
}

TEST_F(FirstLaunch, FolderIsCreatedStartPageSaysWhereFinishConfirmsTheSave) {
  ASSERT_FALSE(QFileInfo::exists(path("xdg")));
  Recorder rec;
  {
    OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
    wiz.setAsker(rec.asker());
    wiz.setClock(fixedNow);
    wiz.show();
    wiz.activateWindow();
    QApplication::processEvents();
    const QString history = path("xdg") + "/auvballast/history.sqlite";
    EXPECT_TRUE(find<QLabel>(wiz, "error")->text().isEmpty()) << find<QLabel>(wiz, "error")->text().toStdString();
    EXPECT_EQ(find<QLabel>(wiz, "history_location")->text(), "History: " + history);
    // Keyboard only: Enter through start, vehicle, crane, water, result (Finish).
    for (int i = 0; i < 5; ++i) pressEnter(wiz);
    EXPECT_EQ(wiz.result(), QDialog::Accepted) << "stopped on page " << wiz.currentId();
    ASSERT_EQ(rec.asked.size(), 1u);
    EXPECT_FALSE(rec.asked[0].question);
    EXPECT_EQ(rec.asked[0].text,
              "Saved configuration 01-02-03: weighing, water, recommendation and installed state.");
  }
  // After a restart the session is there.
  HistoryStore store((path("xdg") + "/auvballast/history.sqlite").toStdString());
  EXPECT_TRUE(store.configuration("01-02-03").has_value());
  const auto inst = store.latestInstalled("01-02-03", fixedNow());
  ASSERT_TRUE(inst.has_value());
  ASSERT_EQ(inst->points.size(), 4u);
}

// Item 3: the first mission ends with what is installed now; a change the
// technician makes there is what the history keeps, and the next session
// (post mission) starts from it.
TEST_F(FirstLaunch, FirstMissionRecordsWhatIsActuallyInstalled) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.show();
  for (int i = 0; i < 4; ++i) wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
  ASSERT_TRUE(wiz.state().report.has_value());
  const auto& r = *wiz.state().report;
  // Pre-filled: what was in each point plus the recommended change.
  for (int i = 0; i < 4; ++i) {
    auto* in = find<NumberInput>(wiz, QString("installed_now_%1").arg(i).toLatin1().constData());
    EXPECT_NEAR(in->value(), wiz.state().crane.installed_kg[static_cast<std::size_t>(i)] + r.points[static_cast<std::size_t>(i)].add_kg,
                1e-9);
  }
  typeInto(find<NumberInput>(wiz, "installed_now_0"), "9.6");
  wiz.button(QWizard::FinishButton)->click();
  EXPECT_EQ(wiz.result(), QDialog::Accepted);
  HistoryStore store((path("xdg") + "/auvballast/history.sqlite").toStdString());
  const auto inst = store.latestInstalled("01-02-03", fixedNow());
  ASSERT_TRUE(inst.has_value());
  EXPECT_EQ(inst->points[0].name, "fore_starboard");
  EXPECT_DOUBLE_EQ(inst->points[0].mass_kg, 9.6);
  EXPECT_NEAR(inst->points[1].mass_kg, wiz.state().crane.installed_kg[1] + r.points[1].add_kg, 1e-9);

  // Post mission on this configuration: the log page starts from it.
  OperatorWizard next(makeEmptyState(AUV_RESOURCE_DIR));
  next.setClock([] { return fixedNow() + std::chrono::hours(48); });
  next.show();
  auto* table = find<QTableWidget>(next, "configurations");
  for (int row = 0; row < table->rowCount(); ++row)
    if (table->item(row, 0) && table->item(row, 0)->text() == "01-02-03") table->selectRow(row);
  find<QAbstractButton>(next, "mode_post")->click();
  next.next();
  ASSERT_EQ(next.currentId(), OperatorWizard::kVehicle);
  next.next();
  ASSERT_EQ(next.currentId(), OperatorWizard::kLogImport);
  EXPECT_DOUBLE_EQ(find<NumberInput>(next, "installed_fore_starboard")->value(), 9.6);
}

TEST_F(FirstLaunch, EscapeAndCancelAskWhenThereIsUnsavedInput) {
  Recorder rec;
  rec.answer = false;  // "Stay"
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.setAsker(rec.asker());
  wiz.show();
  wiz.activateWindow();
  QApplication::processEvents();
  // On the start page nothing is entered yet: Escape closes without asking.
  {
    OperatorWizard fresh(makeDemoState(AUV_RESOURCE_DIR));
    Recorder none;
    fresh.setAsker(none.asker());
    fresh.show();
    QTest::keyClick(&fresh, Qt::Key_Escape);
    EXPECT_TRUE(none.asked.empty());
    EXPECT_EQ(fresh.result(), QDialog::Rejected);
  }
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
  typeInto(find<NumberInput>(wiz, "scale_fs"), "391.7");
  QTest::keyClick(wiz.currentPage(), Qt::Key_Escape);
  ASSERT_EQ(rec.asked.size(), 1u);
  EXPECT_TRUE(rec.asked[0].question);
  EXPECT_EQ(rec.asked[0].title, "Close without saving?");
  EXPECT_TRUE(wiz.isVisible());  // stayed
  wiz.button(QWizard::CancelButton)->click();
  EXPECT_EQ(rec.asked.size(), 2u);
  EXPECT_TRUE(wiz.isVisible());
  // The question wrote the unfinished session, so closing loses nothing.
  const SavedSession s = readSessionFile(autosaveFilePath().toStdString(), AUV_RESOURCE_DIR);
  EXPECT_DOUBLE_EQ(s.state.crane.weighing.scales_kg[0], 391.7);
  rec.answer = true;
  wiz.button(QWizard::CancelButton)->click();
  EXPECT_FALSE(wiz.isVisible());
  EXPECT_EQ(wiz.result(), QDialog::Rejected);
}

// A crash right after typing (no Tab, no page change) loses nothing: the
// autosave runs shortly after the last key.
TEST_F(FirstLaunch, AutosaveKeepsAValueStillBeingTyped) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.show();
  wiz.activateWindow();
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
  QFile::remove(autosaveFilePath());  // the page change wrote one
  auto* fp = find<NumberInput>(wiz, "scale_fp");
  auv::testing::clickInto(fp);
  QTest::keyClicks(focused(), "391.7");  // still in the field
  EXPECT_FALSE(QFileInfo::exists(autosaveFilePath()));
  QTest::qWait(OperatorWizard::autosaveDelayMs + 300);
  ASSERT_TRUE(QFileInfo::exists(autosaveFilePath()));
  const SavedSession s = readSessionFile(autosaveFilePath().toStdString(), AUV_RESOURCE_DIR);
  EXPECT_DOUBLE_EQ(s.state.crane.weighing.scales_kg[1], 391.7);
  EXPECT_EQ(s.page_id, OperatorWizard::kCraneWeighing);
  EXPECT_EQ(fp->text(), "391.7");  // the autosave did not touch the field
}

TEST_F(FirstLaunch, FinishWithoutAHistoryAsksBeforeClosing) {
  // A history that cannot exist (a file where its folder should be).
  QFile blocker(path("xdg"));
  ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
  blocker.close();
  Recorder rec;
  rec.answer = false;
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.setAsker(rec.asker());
  wiz.show();
  EXPECT_NE(find<QLabel>(wiz, "error")->text().indexOf("cannot be opened"), -1);
  for (int i = 0; i < 4; ++i) wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
  wiz.button(QWizard::FinishButton)->click();
  ASSERT_EQ(rec.asked.size(), 1u);
  EXPECT_EQ(rec.asked[0].title, "Nothing will be saved");
  EXPECT_TRUE(wiz.isVisible());
  rec.answer = true;
  wiz.button(QWizard::FinishButton)->click();
  EXPECT_FALSE(wiz.isVisible());
}

// Item 8 on the first-mission pages of both vehicle kinds: Tab from the
// page's fields ends on Next/Finish, Enter with the focus on Back goes
// forward, and no shortcut letter is used twice on a page.
TEST_F(FirstLaunch, KeyboardOnEveryFirstMissionPage) {
  for (bool glider : {false, true}) {
    OperatorWizard wiz(glider ? makeSlocumDemoState(AUV_RESOURCE_DIR) : makeDemoState(AUV_RESOURCE_DIR));
    wiz.show();
    wiz.activateWindow();
    QApplication::processEvents();
    for (int step = 0; step < 8; ++step) {
      const int id = wiz.currentId();
      const std::string where = wiz.currentPage()->title().toStdString();
      EXPECT_EQ(auv::testing::duplicateMnemonics(wiz), QStringList()) << where;
      EXPECT_EQ(auv::testing::internalWords(wiz.currentPage()), QStringList())
          << where << ": " << auv::testing::internalWords(wiz.currentPage()).join(" / ").toStdString();
      const bool last = wiz.nextId() == -1;
      QWidget* after = auv::testing::widgetAfterPageByTab(wiz);
      EXPECT_EQ(after, wiz.button(last ? QWizard::FinishButton : QWizard::NextButton)) << where;
      if (last) break;
      if (wiz.button(QWizard::BackButton)->isVisible()) {
        wiz.button(QWizard::BackButton)->setFocus();
        pressEnter(wiz);
      } else {
        wiz.next();
      }
      ASSERT_NE(wiz.currentId(), id) << where << ": Enter on Back must go to the next page";
    }
  }
}

}  // namespace auv::ui
