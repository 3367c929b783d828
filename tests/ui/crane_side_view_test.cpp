// The crane weighing page's side view: it draws the readings typed on the
// page at the rope stations typed on the page, and the CG the readings give
// (thesis eq. 4.1: x_G = sum m_i x_i / sum m_i over the four part scales).
#include <gtest/gtest.h>

#include "widgets/number_input.h"

#include "screenshot.h"
#include "ui_fixture.h"
#include "widgets/crane_side_view.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
using auv::testing::find;

class CraneSideViewTest : public auv::testing::UiTest {};

TEST_F(CraneSideViewTest, ShowsWhereEachScaleHangsWhatItReadsAndTheCg) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  wiz.next();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
  auto* view = find<CraneSideView>(wiz, "crane_side_view");
  const auto& w = wiz.state().crane.weighing;
  const CraneSideViewData& d = view->data();
  EXPECT_DOUBLE_EQ(d.length_m, 5.23);  // the profile's hull
  EXPECT_DOUBLE_EQ(d.rope_fore_x_m, w.rope_x_fore_m);
  EXPECT_DOUBLE_EQ(d.rope_aft_x_m, w.rope_x_aft_m);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(d.scales_kg[i], w.scales_kg[i]);
  EXPECT_DOUBLE_EQ(d.total_kg, 1565.2);
  auto cgOracle = [](const CraneSideViewData& v) {
    const double fore = v.scales_kg[0] + v.scales_kg[1], aft = v.scales_kg[2] + v.scales_kg[3];
    return (fore * v.rope_fore_x_m + aft * v.rope_aft_x_m) / (fore + aft);
  };
  ASSERT_TRUE(d.cg_x_m.has_value());
  EXPECT_NEAR(*d.cg_x_m, cgOracle(d), 1e-9);
  const double cg_before = *d.cg_x_m;

  // Typing follows at once: the fore rope 10 cm further aft moves the CG aft.
  auto* fore = find<NumberInput>(wiz, "rope_fore");
  fore->setValue(fore->value() - 0.1);
  EXPECT_DOUBLE_EQ(view->data().rope_fore_x_m, fore->value());
  EXPECT_NEAR(*view->data().cg_x_m, cgOracle(view->data()), 1e-9);
  EXPECT_LT(*view->data().cg_x_m, cg_before - 0.05);
  fore->setValue(fore->value() + 0.1);

  const QImage img = auv::testing::shot(*view, "06_crane_side_view");
  // Two scale boxes (amber), the hull and its outline are drawn.
  EXPECT_GT(auv::testing::colourFraction(img, QColor(255, 214, 102), 8) * img.width() * img.height(), 2 * 100.0);
  EXPECT_GT(auv::testing::colourFraction(img, QColor(230, 236, 242), 4), 0.1);
}

}  // namespace auv::ui
