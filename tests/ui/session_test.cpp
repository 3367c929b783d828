// Everyday quality: autosave and resume, remembered window and folder, help,
// and the Norwegian translation.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include "widgets/number_input.h"
#include <QFile>
#include <QFrame>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QTextBrowser>
#include <QtTest/QTest>

#include "screenshot.h"
#include "ui_fixture.h"
#include "widgets/help_dialog.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"
#include "wizard/session_json.h"
#include "wizard/translations.h"

namespace auv::ui {
using auv::testing::find;
using auv::testing::shot;

class Session : public auv::testing::UiTest {};

TEST_F(Session, AutosaveOnEveryPageAndResumeWhereItStopped) {
  const QString file = path("session.json");
  {
    OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
    wiz.setClock(fixedNow);
    wiz.show();
    EXPECT_FALSE(QFile::exists(file));  // nothing entered on the start page yet
    wiz.next();
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
    find<NumberInput>(wiz, "scale_fs")->setValue(392.8);
    find<NumberInput>(wiz, "total")->setValue(1565.7);
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kWater);
    find<NumberInput>(wiz, "temperature")->setValue(7.25);
    // The laptop dies here: no Finish, no Cancel.
  }
  ASSERT_TRUE(QFile::exists(file));
  const SavedSession saved = readSessionFile(file.toStdString(), AUV_RESOURCE_DIR);
  EXPECT_EQ(saved.page_id, OperatorWizard::kWater);
  EXPECT_EQ(saved.saved_at, "2026-05-20T12:00:00Z");
  EXPECT_DOUBLE_EQ(saved.state.crane.weighing.scales_kg[0], 392.8);

  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  auto* banner = find<QFrame>(wiz, "resume_banner");
  ASSERT_TRUE(banner->isVisible());
  const QString offer = find<QLabel>(wiz, "resume_text")->text();
  EXPECT_NE(offer.indexOf("2026-05-20 12:00:00 UTC"), -1) << offer.toStdString();
  EXPECT_NE(offer.indexOf("01-02-03"), -1);
  EXPECT_NE(offer.indexOf("Mission water"), -1);
  shot(wiz, "00b_start_resume");
  find<QPushButton>(wiz, "resume")->click();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kWater);
  wiz.back();
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "scale_fs")->value(), 392.8);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "total")->value(), 1565.7);
  wiz.next();
  // The temperature typed on the page it stopped on was not yet stored (the
  // autosave runs on page changes): the page shows the last stored value.
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "temperature")->value(), 6.5);
  wiz.next();
  wiz.button(QWizard::FinishButton)->click();
  EXPECT_EQ(wiz.result(), QDialog::Accepted);
  EXPECT_FALSE(QFile::exists(file));  // finished: nothing left to resume
}

TEST_F(Session, SlocumSessionRoundTripsThroughTheTankFileFormat) {
  WizardState s = makeSlocumDemoState(AUV_RESOURCE_DIR);
  const auto j = sessionToJson(s, OperatorWizard::kRollTest, "2026-05-20T12:00:00Z");
  const SavedSession back = sessionFromJson(j.dump(), "session.json", AUV_RESOURCE_DIR);
  const TankWeighing& a = s.tank;
  const TankWeighing& b = back.state.tank;
  EXPECT_EQ(back.state.vehicle->id, "slocum_g2");
  EXPECT_DOUBLE_EQ(b.readings.bow_scale_kg, a.readings.bow_scale_kg);
  EXPECT_DOUBLE_EQ(b.readings.target.density_kgm3, 1026.0);
  EXPECT_EQ(b.ballast.item_kg, a.ballast.item_kg);
  ASSERT_TRUE(b.roll_test && b.bottles_after_tank_step_kg);
  ASSERT_EQ(b.roll_test->applied.size(), 3u);
  EXPECT_DOUBLE_EQ(b.roll_test->applied[2].roll_rad, -0.16);
  EXPECT_FALSE(b.roll_test->applied[2].starboard);
  EXPECT_EQ(*b.bottles_after_tank_step_kg, *a.bottles_after_tank_step_kg);
  EXPECT_FALSE(back.state.tank_water_salt);
}

TEST_F(Session, DiscardRemovesTheUnfinishedSession) {
  {
    OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
    wiz.show();
    wiz.next();
    wiz.next();
  }
  ASSERT_TRUE(QFile::exists(path("session.json")));
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.show();
  ASSERT_TRUE(find<QFrame>(wiz, "resume_banner")->isVisible());
  find<QPushButton>(wiz, "discard")->click();
  EXPECT_FALSE(find<QFrame>(wiz, "resume_banner")->isVisible());
  EXPECT_FALSE(QFile::exists(path("session.json")));
}

TEST_F(Session, DamagedAutosaveIsReportedNotFatal) {
  QFile f(path("session.json"));
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write("{\"format\": \"auvballast-gui-session\", \"version\": 1, \"page\": 3, \"configuration\": ");
  f.close();
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.show();
  ASSERT_TRUE(find<QFrame>(wiz, "resume_banner")->isVisible());
  EXPECT_NE(find<QLabel>(wiz, "resume_text")->text().indexOf("cannot be read"), -1);
  EXPECT_FALSE(find<QPushButton>(wiz, "resume")->isEnabled());
}

TEST_F(Session, WindowGeometryIsRemembered) {
  {
    OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
    wiz.show();
    wiz.resize(1111, 777);
    QApplication::processEvents();
    wiz.reject();
  }
  OperatorWizard again(makeEmptyState(AUV_RESOURCE_DIR));
  EXPECT_EQ(again.size(), QSize(1111, 777));
}

TEST_F(Session, HelpOpensTheTechniciansGuide) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.show();
  wiz.activateWindow();
  QApplication::processEvents();
  QTest::keyClick(&wiz, Qt::Key_F1);
  ASSERT_NE(wiz.helpDialog(), nullptr);
  EXPECT_TRUE(wiz.helpDialog()->isVisible());
  const QString text = wiz.helpDialog()->browser()->toPlainText();
  EXPECT_NE(text.indexOf("Slocum glider: the tank sequence"), -1);
  EXPECT_NE(text.indexOf("Roll test"), -1);
  EXPECT_NE(text.indexOf("Post mission"), -1);
  EXPECT_NE(text.indexOf("First mission"), -1);
  wiz.helpDialog()->resize(820, 700);
  auv::testing::screenshot(*wiz.helpDialog(), "40_help");  // the guide's own pictures change with the goldens
  // The Help button does the same.
  wiz.helpDialog()->hide();
  wiz.button(QWizard::HelpButton)->click();
  EXPECT_TRUE(wiz.helpDialog()->isVisible());
}

TEST_F(Session, NorwegianTranslation) {
  ASSERT_TRUE(installTranslation(QLocale(QLocale::NorwegianBokmal)));
  {
    OperatorWizard wiz(makeSlocumDemoState(AUV_RESOURCE_DIR));
    wiz.setClock(fixedNow);
    wiz.resize(1000, 760);
    EXPECT_EQ(wiz.page(OperatorWizard::kVehicle)->title(), "Fartøy og konfigurasjon");
    EXPECT_EQ(wiz.page(OperatorWizard::kTankWeighing)->title(), "Veiing av Slocum i tank");
    EXPECT_EQ(wiz.buttonText(QWizard::NextButton), "&Neste >");
    wiz.show();
    wiz.next();
    wiz.next();
    ASSERT_EQ(wiz.currentId(), OperatorWizard::kTankWeighing);
    const QString result = find<QLabel>(wiz, "tank_result")->text();
    EXPECT_NE(result.indexOf("I tanken"), -1) << result.toStdString();
    shot(wiz, "30_tank_weighing_nb");
  }
  removeTranslation();
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  EXPECT_EQ(wiz.page(OperatorWizard::kVehicle)->title(), "Vehicle and configuration");
}

}  // namespace auv::ui
