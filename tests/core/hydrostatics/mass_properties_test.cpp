#include "hydrostatics/mass_properties.h"

#include <gtest/gtest.h>

#include <vector>

#include "common/input_error.h"

namespace auv {

TEST(MassProperties, ParticleSystemCentroid) {
  // Two equal masses 2 m apart and a third: hand-computed centroid.
  std::vector<MassItem> items = {{1.0, {1, 0, 0}}, {1.0, {-1, 0, 0}}, {2.0, {0, 2, -1}}};
  const auto mp = massProperties(items);
  EXPECT_DOUBLE_EQ(mp.mass_kg, 4.0);
  EXPECT_DOUBLE_EQ(mp.cg_m.x(), 0.0);
  EXPECT_DOUBLE_EQ(mp.cg_m.y(), 1.0);
  EXPECT_DOUBLE_EQ(mp.cg_m.z(), -0.5);
}

TEST(MassProperties, AddingThenRemovingAPieceRestoresTheCg) {
  MassProperties mp = massProperties(std::vector<MassItem>{{100.0, {0.1, 0.02, 0.03}}});
  const Eigen::Vector3d cg0 = mp.cg_m;
  mp.add({4.8, {1.0, 0.3, 0}});
  EXPECT_GT(mp.cg_m.x(), cg0.x());
  mp.add({-4.8, {1.0, 0.3, 0}});
  EXPECT_NEAR((mp.cg_m - cg0).norm(), 0.0, 1e-15);
}

TEST(MassProperties, NonPositiveTotalIsAnInputError) {
  EXPECT_THROW(massProperties(std::vector<MassItem>{{0.0, {0, 0, 0}}}), InputError);
}

}  // namespace auv
