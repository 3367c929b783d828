#include "weighing/crane_weighing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.h"

namespace auv {
namespace {
CraneWeighing thesisCase(double fs, double fp, double as, double ap, double total) {
  CraneWeighing w;
  w.scales_kg = {fs, fp, as, ap};
  w.total_kg = total;
  w.rope_x_fore_m = 1.0;
  w.rope_x_aft_m = -1.0;
  w.rope_y_m = 0.25;
  return w;
}
}  // namespace

TEST(CraneWeighing, ThesisCase3CgIsForwardByHandCalculation) {
  // Table F.1 case 3: 386.5, 386.5, 362.5, 362.5 of 1498 with ropes at +-1 m:
  // x_G = (773 - 725) / 1498 m = 32.04 mm, y_G = 0.
  const auto r = weighCrane(thesisCase(386.5, 386.5, 362.5, 362.5, 1498.0));
  EXPECT_NEAR(r.mass.cg_m.x(), 48.0 / 1498.0, 1e-12);
  EXPECT_NEAR(r.mass.cg_m.y(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(r.mass.mass_kg, 1498.0);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(CraneWeighing, ThesisCase4RollOffset) {
  // 378.5/370.5/378.5/370.5: y_G = 0.25 * (757 - 741) / 1498.
  const auto r = weighCrane(thesisCase(378.5, 370.5, 378.5, 370.5, 1498.0));
  EXPECT_NEAR(r.mass.cg_m.y(), 0.25 * 16.0 / 1498.0, 1e-12);
  EXPECT_NEAR(r.mass.cg_m.x(), 0.0, 1e-12);
}

TEST(CraneWeighing, UncertaintyFollowsScaleResolution) {
  // Symmetric load: sigma_x = (res/sqrt 12) * sqrt(4 * 1^2) / M.
  auto w = thesisCase(374.5, 374.5, 374.5, 374.5, 1498.0);
  w.scale_resolution_kg = 0.5;
  const auto r = weighCrane(w);
  EXPECT_NEAR(r.cg_sigma_m.x(), 0.5 / std::sqrt(12.0) * 2.0 / 1498.0, 1e-12);
  EXPECT_NEAR(r.cg_sigma_m.y(), 0.5 / std::sqrt(12.0) * 0.5 / 1498.0, 1e-12);
}

TEST(CraneWeighing, SumMismatchWarnsThenRefuses) {
  auto warn = weighCrane(thesisCase(374.5, 374.5, 374.5, 377.5, 1498.0));
  ASSERT_EQ(warn.warnings.size(), 1u);
  EXPECT_NEAR(warn.sum_mismatch_kg, 3.0, 1e-12);
  try {
    weighCrane(thesisCase(374.5, 374.5, 374.5, 474.5, 1498.0));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "scales");
    EXPECT_NE(std::string(e.what()).find("1598.00 kg but the total is 1498.00 kg"), std::string::npos);
  }
}

TEST(CraneWeighing, BadReadingsAreNamed) {
  try {
    weighCrane(thesisCase(374.5, -1, 374.5, 374.5, 1498.0));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "scales.fore_port");
  }
  auto w = thesisCase(374.5, 374.5, 374.5, 374.5, 1498.0);
  w.rope_x_fore_m = -2.0;
  EXPECT_THROW(weighCrane(w), InputError);
  w = thesisCase(NAN, 374.5, 374.5, 374.5, 1498.0);
  EXPECT_THROW(weighCrane(w), InputError);
}

}  // namespace auv
