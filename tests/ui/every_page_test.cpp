// Issue 14 items 7 and 8 on every page of every wizard sequence (page_walk.h):
// no internal words (CLI flags, code paths, JSON paths, ids with '_'), Enter
// is Next/Finish from the page's last field, Tab ends on Next, no shortcut
// letter twice on a page, and every page fits a 1366 x 768 screen.
#include <gtest/gtest.h>

#include <QPushButton>
#include <QScreen>
#include <QtTest/QTest>

#include "page_walk.h"
#include "typing.h"
#include "ui_fixture.h"

namespace auv::ui {
using auv::testing::WizardSequence;

namespace {

// 1366 x 768 less the window's title bar and a panel: what a wizard page may need.
constexpr int kScreenW = 1366, kScreenH = 720;

// The checks of one page; `where` names sequence and page for the messages.
void checkPage(OperatorWizard& wiz, const std::string& where) {
  for (const auto& t : auv::testing::visibleTexts(wiz)) {
    const QStringList bad = auv::testing::internalWordsIn(t.text);
    EXPECT_TRUE(bad.isEmpty()) << where << ", " << t.where.toStdString() << ": " << bad.join(", ").toStdString()
                               << " in \"" << t.text.left(300).toStdString() << "\"";
  }
  EXPECT_EQ(auv::testing::duplicateMnemonics(wiz).join(", ").toStdString(), "") << where;
  const bool last = wiz.nextId() == -1;
  auto* forward = qobject_cast<QPushButton*>(wiz.button(last ? QWizard::FinishButton : QWizard::NextButton));
  ASSERT_NE(forward, nullptr);
  EXPECT_TRUE(forward->isDefault()) << where << ": " << (last ? "Finish" : "Next") << " is not the default button";
  // A focused auto-default button would take Enter instead of Next.
  for (QPushButton* b : wiz.currentPage()->findChildren<QPushButton*>()) {
    if (!b->isVisibleTo(wiz.currentPage())) continue;
    EXPECT_FALSE(b->autoDefault()) << where << ": Enter on '" << b->text().toStdString() << "' presses it, not Next";
  }
  if (auv::testing::lastPageWidgetByTab(wiz)) {
    EXPECT_EQ(auv::testing::widgetAfterPageByTab(wiz), forward) << where << ": Tab from the last field must land on "
                                                                << (last ? "Finish" : "Next");
  }
  const QSize min = wiz.minimumSizeHint().expandedTo(wiz.minimumSize());
  EXPECT_LE(min.width(), kScreenW) << where << ": needs " << min.width() << " px wide";
  EXPECT_LE(min.height(), kScreenH) << where << ": needs " << min.height() << " px high";
}

// Enter with the focus on the page's last field (as after typing into it).
void pressEnterOnLastField(OperatorWizard& wiz) {
  if (!wiz.isActiveWindow()) QApplication::setActiveWindow(&wiz);
  QWidget* field = auv::testing::lastPageWidgetByTab(wiz);
  if (field) field->setFocus(Qt::TabFocusReason);
  QWidget* target = QApplication::focusWidget() ? QApplication::focusWidget() : wiz.currentPage();
  QTest::keyClick(target, Qt::Key_Return);
  QApplication::processEvents();
}

}  // namespace

class EveryPage : public auv::testing::UiTest, public ::testing::WithParamInterface<std::size_t> {};

TEST_P(EveryPage, WordsKeyboardAndScreenSize) {
  const WizardSequence seq = auv::testing::everyWizardSequence()[GetParam()];
  if (seq.seed_history) seq.seed_history(path("history.sqlite"));
  OperatorWizard wiz(seq.session(dirPath()));
  wiz.setClock(fixedNow);
  wiz.setAutosaveEnabled(false);
  wiz.resize(1000, 760);
  wiz.show();
  wiz.activateWindow();
  QApplication::processEvents();
  int pages = 0;
  for (; pages < 20; ++pages) {
    auv::testing::settlePage(wiz);
    const std::string where = seq.name + ", page " + std::to_string(wiz.currentId()) + " '" +
                              wiz.currentPage()->title().toStdString() + "'";
    checkPage(wiz, where);
    if (wiz.currentId() == seq.last_page) break;
    const int expected = wiz.nextId();
    ASSERT_TRUE(wiz.currentPage()->isComplete()) << where << ": the demo cannot go on ("
                                                 << wiz.state().last_error << ")";
    pressEnterOnLastField(wiz);
    if (expected == -1) {
      QString said;
      for (QLabel* l : wiz.currentPage()->findChildren<QLabel*>())
        if (l->objectName().contains("status") || l->objectName().contains("error")) said += " " + l->text();
      EXPECT_EQ(wiz.result(), QDialog::Accepted) << where << ": Enter on the last page must finish;" << said.toStdString();
      break;
    }
    ASSERT_EQ(wiz.currentId(), expected) << where << ": Enter from the last field must go to the next page ("
                                         << wiz.state().last_error << ")";
  }
  EXPECT_GE(pages, seq.last_page == -1 ? 3 : 1) << seq.name;
}

INSTANTIATE_TEST_SUITE_P(Sequences, EveryPage,
                         ::testing::Range<std::size_t>(0, auv::testing::everyWizardSequence().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& i) {
                           const std::string name = auv::testing::everyWizardSequence()[i.param].name;
                           std::string n;
                           for (char c : name) {
                             if (c == '(') break;
                             if (std::isalnum(static_cast<unsigned char>(c))) n += c;
                           }
                           return n;
                         });

}  // namespace auv::ui
