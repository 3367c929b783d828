// The Slocum tank sequence: start -> vehicle -> tank weighing -> roll test ->
// result, on Baird 2007 App. B (resources/examples/slocum_tank_weighing.json).
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include "widgets/number_input.h"
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest/QTest>
#include <cmath>

#include "history/store.h"
#include "pages/roll_test_page.h"
#include "screenshot.h"
#include "ui_fixture.h"
#include "widgets/weight_map_widget.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
using auv::testing::find;
using auv::testing::shot;

class SlocumPages : public auv::testing::UiTest {
 protected:
  // Report §4.1 by hand: the glider displaces (dry mass - scale readings) in
  // the tank; its aluminium hull (alpha = 7e-5 /degC) shrinks from 18.5 to
  // 3.5 degC; neutral mass = that volume times the target density.
  static double neutralMassOracle() {
    const double m_tank = 52.2 - (0.650 + 0.520);
    const double v_tank = m_tank / 1000.0;
    const double v_target = v_tank * (1.0 + 7e-5 * (3.5 - 18.5));
    return v_target * 1026.0;
  }
};

TEST_F(SlocumPages, GliderBranchesToTankPagesWithTheReportSession) {
  OperatorWizard wiz(makeSlocumDemoState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
  EXPECT_EQ(find<QComboBox>(wiz, "vehicle")->currentData().toString(), "slocum_g2");
  EXPECT_NE(find<QLabel>(wiz, "summary")->text().indexOf("tank method"), -1);
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kTankWeighing);  // kind "glider" -> tank, not crane
  shot(wiz, "10_tank_weighing");
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "dry_mass")->value(), 52.2);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "bow_scale")->value(), 650);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "aft_scale")->value(), 520);
  EXPECT_EQ(find<QComboBox>(wiz, "tank_water")->currentIndex(), 0);  // fresh
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "tank_density")->value(), 1000.0);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "ballast_fore_port")->value(), 208);
  const QString result = find<QLabel>(wiz, "tank_result")->text();
  EXPECT_NE(result.indexOf("51.030 kg"), -1) << result.toStdString();  // 52.2 - 0.65 - 0.52
  EXPECT_NE(result.indexOf(QString::number(neutralMassOracle(), 'f', 3) + " kg"), -1) << result.toStdString();
  EXPECT_TRUE(wiz.currentPage()->isComplete());

  // Salt tank water: the density range opens up and the neutral mass follows
  // the volume V = 51.03 kg / rho_tank.
  auto* water = find<QComboBox>(wiz, "tank_water");
  water->setCurrentIndex(1);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "tank_density")->value(), 1025.0);
  const double salt_neutral = 51.03 / 1025.0 * (1.0 + 7e-5 * (3.5 - 18.5)) * 1026.0;
  EXPECT_NE(find<QLabel>(wiz, "tank_result")->text().indexOf(QString::number(salt_neutral, 'f', 3)), -1);
  water->setCurrentIndex(0);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "tank_density")->value(), 1000.0);

  // An implausible reading is named next to the fields and blocks Next.
  auto* dry = find<NumberInput>(wiz, "dry_mass");
  dry->setValue(1.0);  // less than the scales' apparent weight allows
  EXPECT_FALSE(find<QLabel>(*wiz.currentPage(), "error")->text().isEmpty());
  EXPECT_FALSE(wiz.currentPage()->isComplete());
  dry->setValue(52.2);
  EXPECT_TRUE(wiz.currentPage()->isComplete());

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kRollTest);
  shot(wiz, "11_roll_test");
  auto* page = qobject_cast<RollTestPage*>(wiz.currentPage());
  ASSERT_NE(page, nullptr);
  EXPECT_EQ(page->rowCount(), 3);
  EXPECT_TRUE(find<QCheckBox>(wiz, "after_step")->isChecked());
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "after_aft_upper")->value(), 288);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "initial_roll")->value(), 0.09);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "roll_reading_2")->value(), -0.16);
  // The report's printed h-arm for this session (App. B): 5.45 mm.
  const QString roll = find<QLabel>(wiz, "roll_result")->text();
  EXPECT_NE(roll.indexOf("5.45 mm"), -1) << roll.toStdString();

  // The usual sign mistake: the mass on the other rail than the reading says.
  auto* rail = find<QComboBox>(wiz, "roll_rail_0");
  rail->setCurrentIndex(1);  // starboard, but the glider rolled to port
  QString message;
  for (auto* l : wiz.currentPage()->findChildren<QLabel*>("error")) message += l->text();
  EXPECT_NE(message.indexOf("roll_test.applied[0]"), -1) << message.toStdString();
  EXPECT_FALSE(wiz.currentPage()->isComplete());
  rail->setCurrentIndex(0);
  EXPECT_TRUE(wiz.currentPage()->isComplete());

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
  const QImage img = shot(wiz, "12_slocum_result");
  ASSERT_TRUE(wiz.state().report.has_value()) << wiz.state().last_error;
  const auto& r = *wiz.state().report;
  EXPECT_EQ(r.method, "tank");
  EXPECT_EQ(wiz.currentPage()->title(), "Ballast change after the tank weighing");
  auto* table = find<QTableWidget>(wiz, "changes");
  ASSERT_EQ(table->rowCount(), 6);
  for (int i = 0; i < 6; ++i) {
    const auto& p = r.points[static_cast<std::size_t>(i)];
    const long grams = std::lround(p.add_kg * 1000.0);
    EXPECT_NE(table->item(i, 1)->text().indexOf(QString("%1 g").arg(std::abs(grams))), -1)
        << table->item(i, 1)->text().toStdString();
  }
  // 162 g of lead shot from the upper to the lower aft bottle: one block
  // per bottle on the map, labelled with the count, not 162 specks.
  auto* map = find<WeightMapWidget>(wiz, "weight_map");
  int pieces = 0;
  for (const auto& p : r.points)
    for (const auto& pc : p.pieces) pieces += std::abs(pc.count);
  EXPECT_EQ(map->model().piecesToAdd() + map->model().piecesToRemove(), pieces);
  EXPECT_TRUE(map->model().grams);
  int blocks = 0;
  for (const auto& p : map->model().points) blocks += static_cast<int>(p.blocks().size());
  EXPECT_LE(blocks, 6);
  EXPECT_GT(auv::testing::colourFraction(img, QColor(46, 160, 67), 10), 0.0);
  EXPECT_GT(auv::testing::colourFraction(img, QColor(210, 50, 50), 10), 0.0);
  EXPECT_NE(find<QLabel>(wiz, "messages")->text().indexOf("Roll test: h = 5.45 mm"), -1);

  wiz.button(QWizard::FinishButton)->click();
  HistoryStore store(path("history.sqlite").toStdString());
  const auto events = store.history("49-1-1");
  ASSERT_EQ(events.size(), 4u);  // weighing, water, recommendation, installed state
  EXPECT_EQ(events[3].kind, EventKind::kInstalled);
  const auto& w = std::get<Weighing>(events[0].record);
  EXPECT_EQ(w.method, WeighingMethod::kTank);
  EXPECT_DOUBLE_EQ(w.inputs["tank"]["bow_scale_g"].get<double>(), 650.0);
  EXPECT_DOUBLE_EQ(*std::get<WaterCondition>(events[1].record).density_kg_m3, 1026.0);
}

TEST_F(SlocumPages, BackAndForthKeepsTheRollTable) {
  OperatorWizard wiz(makeSlocumDemoState(AUV_RESOURCE_DIR));
  wiz.show();
  wiz.next();
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kRollTest);
  find<QPushButton>(wiz, "add_row")->click();
  find<NumberInput>(wiz, "roll_mass_3")->setValue(0.8);
  find<NumberInput>(wiz, "roll_reading_3")->setValue(-0.19);
  wiz.next();
  wiz.back();
  wiz.back();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kTankWeighing);
  wiz.next();
  auto* page = qobject_cast<RollTestPage*>(wiz.currentPage());
  ASSERT_EQ(page->rowCount(), 4);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "roll_mass_3")->value(), 0.8);
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "roll_reading_3")->value(), -0.19);
}

TEST_F(SlocumPages, KeyboardOnlyCompletesTheTankSequence) {
  OperatorWizard wiz(makeSlocumDemoState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.show();
  wiz.activateWindow();
  QApplication::processEvents();
  const int expected[] = {OperatorWizard::kVehicle, OperatorWizard::kTankWeighing, OperatorWizard::kRollTest,
                          OperatorWizard::kFirstMissionResult};
  for (int id : expected) {
    QWidget* focus = QApplication::focusWidget() ? QApplication::focusWidget() : wiz.currentPage();
    QTest::keyClick(focus, Qt::Key_Return);
    QApplication::processEvents();
    ASSERT_EQ(wiz.currentId(), id);
  }
  QWidget* focus = QApplication::focusWidget() ? QApplication::focusWidget() : wiz.currentPage();
  QTest::keyClick(focus, Qt::Key_Return);
  EXPECT_EQ(wiz.result(), QDialog::Accepted);
}

}  // namespace auv::ui
