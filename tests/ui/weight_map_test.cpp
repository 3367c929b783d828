#include "widgets/weight_map_widget.h"

#include <gtest/gtest.h>

#include "screenshot.h"

namespace auv::ui {

TEST(WeightMap, RemovalsAreRedAndAdditionsGreen) {
  WeightMapModel m;
  m.length_m = 5.23;
  m.diameter_m = 0.75;
  m.points = {{"fs", "FS", 1.03, 0.325, 4.8, {{2.4, 2}}, 4.8}, {"ap", "AP", -0.49, -0.325, 9.6, {{4.8, -1}}, -4.8}};
  EXPECT_EQ(m.piecesToAdd(), 2);
  EXPECT_EQ(m.piecesToRemove(), 1);
  WeightMapWidget w;
  w.resize(760, 300);
  w.setModel(m);
  const QImage img = auv::testing::screenshot(w, "weight_map_unit");
  const double green = auv::testing::colourFraction(img, QColor(46, 160, 67), 10);
  const double red = auv::testing::colourFraction(img, QColor(210, 50, 50), 10);
  EXPECT_GT(green, 0.0);
  EXPECT_GT(red, 0.0);
  // Two 2.4 kg squares vs one 4.8 kg square: areas scale with mass.
  EXPECT_NEAR(green / red, 2 * 2.4 / 4.8, 0.25);
}

}  // namespace auv::ui
