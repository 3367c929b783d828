// The weight map's point labels: never on top of each other, never on the
// hull outline, and inside the widget - for HUGIN's four points and for the
// Slocum's six (two of which share x and y in the top view).
#include <gtest/gtest.h>

#include "firstmission/hugin_first_mission.h"
#include "firstmission/slocum_first_mission.h"
#include "screenshot.h"
#include "widgets/weight_map_widget.h"
#include "wizard/demo_state.h"

namespace auv::ui {
namespace {

void expectLabelsApart(const WeightMapWidget& w) {
  const auto& r = w.labelRects();
  ASSERT_EQ(r.size(), w.model().points.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_TRUE(QRectF(w.rect()).contains(r[i])) << w.model().points[i].label;
    EXPECT_FALSE(r[i].intersects(w.hullRect())) << w.model().points[i].label;  // off the outline
    for (std::size_t j = i + 1; j < r.size(); ++j) {
      EXPECT_FALSE(r[i].intersects(r[j])) << w.model().points[i].label << " / " << w.model().points[j].label;
    }
  }
}

}  // namespace

TEST(WeightMapLabels, HuginLabelsStayOffTheHullAndApart) {
  const WizardState s = makeDemoState(AUV_RESOURCE_DIR);
  const FirstMissionReport r = craneFirstMission(*s.vehicle, s.crane);
  WeightMapWidget w;
  w.resize(960, 240);
  w.setModel(makeWeightMapModel(*s.vehicle, s.crane.installed_kg, r));
  auv::testing::screenshot(w, "weight_map_labels_hugin");
  expectLabelsApart(w);
}

TEST(WeightMapLabels, SlocumLabelsStayOffTheHullAndApart) {
  const WizardState s = makeSlocumDemoState(AUV_RESOURCE_DIR);
  const FirstMissionReport r = slocumFirstMission(*s.vehicle, s.tank);
  std::vector<double> installed;
  for (const auto& p : s.vehicle->points) installed.push_back(r.details["ballast_now_g"].value(p.name, 0.0) / 1000.0);
  WeightMapWidget w;
  for (int width : {960, 640}) {  // narrow: the labels need more rows
    w.resize(width, 260);
    w.setModel(makeWeightMapModel(*s.vehicle, installed, r));
    auv::testing::screenshot(w, QString("weight_map_labels_slocum_%1").arg(width));
    expectLabelsApart(w);
  }
}

}  // namespace auv::ui
