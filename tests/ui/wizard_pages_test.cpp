#include <gtest/gtest.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFontInfo>
#include <QFontMetrics>
#include <QLabel>
#include <QTableWidget>
#include <QtTest/QTest>
#include <cmath>

#include "screenshot.h"
#include "widgets/weight_map_widget.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
using auv::testing::screenshot;

namespace {
template <class T>
T* find(QWidget& w, const char* name) {
  T* c = w.findChild<T*>(name);
  EXPECT_NE(c, nullptr) << name;
  return c;
}
}  // namespace

TEST(WizardPages, FontsArePresent) {
  // Missing fonts fail silently offscreen (glyphs become boxes).
  EXPECT_FALSE(QFontInfo(qApp->font()).family().isEmpty());
  EXPECT_TRUE(QFontMetrics(qApp->font()).inFont('A'));
}

TEST(WizardPages, DemoWalksVehicleWeighingWaterResult) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.resize(1000, 760);
  screenshot(wiz, "01_vehicle");
  auto* vehicle = find<QComboBox>(wiz, "vehicle");
  EXPECT_EQ(vehicle->currentText(), "hugin1000");
  EXPECT_NE(find<QLabel>(wiz, "summary")->text().indexOf("1498.0 kg"), -1);

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
  screenshot(wiz, "02_crane_weighing");
  EXPECT_DOUBLE_EQ(find<QDoubleSpinBox>(wiz, "scale_fs")->value(), 392.3);
  EXPECT_NE(find<QLabel>(wiz, "sum_check")->text().indexOf("1565.2 kg"), -1);
  EXPECT_TRUE(wiz.currentPage()->isComplete());

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kWater);
  screenshot(wiz, "03_water");
  const QString density = find<QLabel>(wiz, "density")->text();
  EXPECT_NE(density.indexOf("kg/m³"), -1) << density.toStdString();

  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
  const QImage img = screenshot(wiz, "04_first_mission_result");
  ASSERT_TRUE(wiz.state().report.has_value()) << wiz.state().last_error;
  const auto& r = *wiz.state().report;
  auto* table = find<QTableWidget>(wiz, "changes");
  ASSERT_EQ(table->rowCount(), 4);
  EXPECT_EQ(table->item(0, 0)->text(), "Fore / starboard");
  // The table shows exactly the core's numbers.
  for (int i = 0; i < 4; ++i) {
    const double kg = r.points[static_cast<std::size_t>(i)].add_kg;
    EXPECT_NE(table->item(i, 1)->text().indexOf(QString::number(kg, 'f', 1)), -1);
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
}

TEST(WizardPages, WeighingSumMismatchBlocksNext) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.show();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
  auto* fs = find<QDoubleSpinBox>(wiz, "scale_fs");
  fs->setValue(fs->value() + 100);  // a mistyped reading
  EXPECT_FALSE(wiz.currentPage()->isComplete());
  EXPECT_NE(find<QLabel>(wiz, "sum_check")->text().indexOf("re-read"), -1);
  screenshot(wiz, "02b_crane_weighing_sum_error");
}

TEST(WizardPages, KeyboardOnlyReachesTheResult) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.show();
  wiz.activateWindow();
  QApplication::processEvents();
  // Enter presses the default button (Next) from any field on every page.
  for (int i = 0; i < 3; ++i) {
    QWidget* focus = QApplication::focusWidget() ? QApplication::focusWidget() : wiz.currentPage();
    QTest::keyClick(focus, Qt::Key_Return);
    QApplication::processEvents();
  }
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
}

}  // namespace auv::ui
