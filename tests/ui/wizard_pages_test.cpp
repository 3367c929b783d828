// The HUGIN first-mission sequence: start -> vehicle -> crane weighing ->
// water -> result, on the bundled demo weighing, then Finish into the history.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QComboBox>
#include "widgets/number_input.h"
#include <QFontInfo>
#include <QFontMetrics>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest/QTest>
#include <cmath>

#include "history/store.h"
#include "screenshot.h"
#include "ui_fixture.h"
#include "widgets/weight_map_widget.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
using auv::testing::find;
using auv::testing::screenshot;
using auv::testing::shot;

class WizardPages : public auv::testing::UiTest {};

TEST_F(WizardPages, FontsArePresent) {
  // Missing fonts fail silently offscreen (glyphs become boxes).
  EXPECT_FALSE(QFontInfo(qApp->font()).family().isEmpty());
  EXPECT_EQ(QFontInfo(qApp->font()).family(), "DejaVu Sans");
  EXPECT_TRUE(QFontMetrics(qApp->font()).inFont('A'));
  EXPECT_TRUE(QFontMetrics(qApp->font()).inFont(QChar(0x00B3)));  // ³ of kg/m³
  // Every symbol the pages draw (a missing one silently becomes a box):
  // ✓ ✗ spec bands, ⚠ warnings, ▶ ▼ map axes, ↓ drop hint, − × ° ± ³.
  for (char16_t c : {u'✓', u'✗', u'⚠', u'▶', u'▼', u'↓', u'−', u'×', u'°', u'±', u'³', u'…', u'→'}) {
    EXPECT_TRUE(QFontMetrics(qApp->font()).inFont(QChar(c))) << static_cast<int>(c);
  }
}

TEST_F(WizardPages, DemoWalksStartVehicleWeighingWaterResultAndSaves) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  shot(wiz, "01_start");
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kStart);
  // Empty history: only the "new configuration" row.
  EXPECT_EQ(find<QTableWidget>(wiz, "configurations")->rowCount(), 1);

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
  shot(wiz, "02_vehicle");
  EXPECT_EQ(find<QComboBox>(wiz, "vehicle")->currentData().toString(), "hugin1000");
  EXPECT_EQ(find<QLineEdit>(wiz, "configuration")->text(), "01-02-03");
  EXPECT_NE(find<QLabel>(wiz, "summary")->text().indexOf("1498.0 kg"), -1);
  EXPECT_NE(find<QLabel>(wiz, "summary")->text().indexOf("crane scales"), -1);

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
  shot(wiz, "03_crane_weighing");
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "scale_fs")->value(), 392.3);
  // 392.3 + 391.3 + 391.3 + 390.3 = 1565.2 = the hook reading.
  EXPECT_NE(find<QLabel>(wiz, "sum_check")->text().indexOf("1565.2 kg (0.0 kg"), -1);
  EXPECT_TRUE(wiz.currentPage()->isComplete());

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kWater);
  shot(wiz, "04_water");
  const QString density = find<QLabel>(wiz, "density")->text();
  EXPECT_NE(density.indexOf("kg/m³"), -1) << density.toStdString();

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
  const QImage img = shot(wiz, "05_first_mission_result");
  ASSERT_TRUE(wiz.state().report.has_value()) << wiz.state().last_error;
  const auto& r = *wiz.state().report;
  // Weight is the hook reading (thesis eq. 4.1), not a model value.
  EXPECT_DOUBLE_EQ(r.weight_kg, 1565.2);
  auto* table = find<QTableWidget>(wiz, "changes");
  ASSERT_EQ(table->rowCount(), 4);
  EXPECT_EQ(table->item(0, 0)->text(), "Fore / starboard");
  // The table shows exactly the core's numbers.
  for (int i = 0; i < 4; ++i) {
    const double kg = r.points[static_cast<std::size_t>(i)].add_kg;
    EXPECT_NE(table->item(i, 1)->text().indexOf(QString::number(std::abs(kg), 'f', 1)), -1);
  }
  // The map draws one square per piece to add: count the pieces.
  auto* map = find<WeightMapWidget>(wiz, "weight_map");
  int pieces = 0;
  for (const auto& p : r.points)
    for (const auto& pc : p.pieces) pieces += std::abs(pc.count);
  EXPECT_EQ(map->model().piecesToAdd() + map->model().piecesToRemove(), pieces);
  EXPECT_GT(pieces, 0);
  // Each added piece is a green square of side 7 px * sqrt(kg) (less its 1 px
  // outline): the green area must match the added mass.
  double added_area = 0;
  for (const auto& p : r.points)
    for (const auto& pc : p.pieces)
      if (pc.count > 0) added_area += pc.count * std::pow(7.0 * std::sqrt(pc.size_kg) - 1.0, 2);
  const double green = auv::testing::colourFraction(img, QColor(46, 160, 67), 10) * img.width() * img.height();
  EXPECT_GT(green, 0.6 * added_area);
  EXPECT_LT(green, 1.3 * added_area);
  EXPECT_NE(find<QLabel>(wiz, "predicted")->text().indexOf("✓"), -1);

  // Finish: configuration, weighing, water and recommendation in the history.
  wiz.button(QWizard::FinishButton)->click();
  EXPECT_EQ(find<QLabel>(*wiz.currentPage(), "save_status")->text(), "");
  HistoryStore store(path("history.sqlite").toStdString());
  const auto c = store.configuration("01-02-03");
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->vehicle_key, "hugin1000");
  EXPECT_EQ(c->area, "Horten");
  const auto events = store.history("01-02-03");
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0].kind, EventKind::kWeighing);
  EXPECT_EQ(events[1].kind, EventKind::kWater);
  EXPECT_EQ(events[2].kind, EventKind::kRecommendation);
  EXPECT_EQ(events[3].kind, EventKind::kInstalled);
  const auto& w = std::get<Weighing>(events[0].record);
  EXPECT_DOUBLE_EQ(w.inputs["total_kg"].get<double>(), 1565.2);
  EXPECT_DOUBLE_EQ(w.results["weight_kg"].get<double>(), 1565.2);
  const auto& water = std::get<WaterCondition>(events[1].record);
  EXPECT_DOUBLE_EQ(*water.temperature_degC, 6.5);
  EXPECT_EQ(events[0].at, fixedNow());
}

TEST_F(WizardPages, WeighingSumMismatchBlocksNext) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.resize(1000, 760);
  wiz.show();
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
  auto* fs = find<NumberInput>(wiz, "scale_fs");
  fs->setValue(fs->value() + 100);  // a mistyped reading
  EXPECT_FALSE(wiz.currentPage()->isComplete());
  EXPECT_FALSE(wiz.button(QWizard::NextButton)->isEnabled());
  EXPECT_NE(find<QLabel>(wiz, "sum_check")->text().indexOf("re-read"), -1);
  shot(wiz, "03b_crane_weighing_sum_error");
  // Going back and forth keeps what was typed.
  wiz.back();
  wiz.next();
  EXPECT_DOUBLE_EQ(find<NumberInput>(wiz, "scale_fs")->value(), 392.3 + 100);
}

TEST_F(WizardPages, KeyboardOnlyReachesTheResultAndFinishes) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.show();
  wiz.activateWindow();
  QApplication::processEvents();
  // Enter presses the default button (Next, then Finish) from any field on every page.
  for (int i = 0; i < 4; ++i) {
    QWidget* focus = QApplication::focusWidget() ? QApplication::focusWidget() : wiz.currentPage();
    QTest::keyClick(focus, Qt::Key_Return);
    QApplication::processEvents();
  }
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
  QWidget* focus = QApplication::focusWidget() ? QApplication::focusWidget() : wiz.currentPage();
  QTest::keyClick(focus, Qt::Key_Return);
  QApplication::processEvents();
  EXPECT_EQ(wiz.result(), QDialog::Accepted);
  HistoryStore store(path("history.sqlite").toStdString());
  EXPECT_TRUE(store.configuration("01-02-03").has_value());
}

TEST_F(WizardPages, EveryInputHasATooltipAndRoomForGloves) {
  OperatorWizard wiz(makeSlocumDemoState(AUV_RESOURCE_DIR));
  for (int id : wiz.pageIds()) {
    QWizardPage* page = wiz.page(id);
    EXPECT_TRUE(page->findChildren<QAbstractSpinBox*>().isEmpty()) << "page " << id << ": numbers use NumberInput";
    for (auto* s : page->findChildren<NumberInput*>()) {
      EXPECT_FALSE(s->toolTip().isEmpty()) << "page " << id << ": " << s->objectName().toStdString();
      EXPECT_GE(s->minimumHeight(), 32) << s->objectName().toStdString();
      EXPECT_FALSE(s->objectName().isEmpty()) << "page " << id;
    }
    for (auto* e : page->findChildren<QLineEdit*>()) {
      if (qobject_cast<NumberInput*>(e->parent())) continue;  // a number field's own editor
      EXPECT_FALSE(e->toolTip().isEmpty()) << e->objectName().toStdString();
      EXPECT_GE(e->minimumHeight(), 32) << e->objectName().toStdString();
    }
    for (auto* c : page->findChildren<QComboBox*>()) {
      EXPECT_FALSE(c->toolTip().isEmpty()) << c->objectName().toStdString();
      EXPECT_GE(c->minimumHeight(), 32) << c->objectName().toStdString();
    }
  }
}

}  // namespace auv::ui
