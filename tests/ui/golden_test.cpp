// The golden comparison itself: it must pass on the same image and must FAIL
// on a deliberately wrong golden (tests/ui/golden/deliberately_wrong_02_vehicle.png:
// the vehicle page with one digit of the configuration ID changed), or the
// page goldens prove nothing.
#include <gtest/gtest.h>

#include <QLineEdit>
#include <QPainter>
#include <cstdio>

#include "golden.h"
#include "screenshot.h"
#include "ui_fixture.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
using auv::testing::checkGolden;
using auv::testing::compareImages;

class Golden : public auv::testing::UiTest {};

TEST_F(Golden, ComparisonCountsOnlyPixelsBeyondTheTolerance) {
  QImage a(100, 50, QImage::Format_RGB32);
  a.fill(QColor(200, 200, 200));
  QImage b = a;
  EXPECT_EQ(compareImages(a, b, 0).differing, 0);
  b.setPixelColor(3, 4, QColor(210, 200, 200));  // within a tolerance of 16
  b.setPixelColor(5, 6, QColor(200, 160, 200));  // beyond it
  const auto d = compareImages(a, b, 16);
  EXPECT_TRUE(d.same_size);
  EXPECT_EQ(d.differing, 1);
  EXPECT_EQ(d.max_channel_diff, 40);
  EXPECT_DOUBLE_EQ(d.fraction, 1.0 / 5000);
  EXPECT_FALSE(compareImages(a, a.scaled(99, 50), 16).same_size);
}

TEST_F(Golden, DeliberatelyWrongGoldenFails) {
  WizardState s = makeDemoState(AUV_RESOURCE_DIR);
  const bool bless = qEnvironmentVariable("AUV_BLESS_GOLDENS") == "1";
  if (bless) {
    // Re-create the wrong golden from a wrong session, deterministically:
    // ONE digit of the configuration ID differs (01-02-03 -> 01-02-08), the
    // smallest wrong content a page can show.
    s.configuration_id = "01-02-08";
  }
  OperatorWizard wiz(s);
  wiz.resize(1000, 760);
  wiz.show();
  wiz.next();
  const QImage img = auv::testing::screenshot(wiz, "02_vehicle_for_wrong_golden");
  const QString problem = checkGolden(img, "deliberately_wrong_02_vehicle");
  if (bless) return;
  ASSERT_FALSE(problem.isEmpty()) << "a wrong golden passed: the comparison cannot fail";
  EXPECT_NE(problem.indexOf("of the pixels differ"), -1) << problem.toStdString();
  std::printf("[ golden ] one wrong digit: %s\n", qPrintable(problem));
  // And the right golden passes for the same image.
  EXPECT_TRUE(checkGolden(img, "02_vehicle").isEmpty());
}

}  // namespace auv::ui
