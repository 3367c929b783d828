// Issue 14, item 3: the log's `# configuration:` header line pre-fills the
// installed masses of a post-mission session when the history has none.
#include <gtest/gtest.h>

#include "vehicle/vehicle_catalog.h"
#include "wizard/installed_from_log.h"

namespace auv::ui {

class InstalledFromLog : public ::testing::Test {
 protected:
  VehicleProfile hugin = VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000");
  static MissionLog withLine(const std::string& line) {
    MissionLog log;
    log.setMetadata("configuration", line);
    return log;
  }
};

TEST_F(InstalledFromLog, InitialsOrIdsGiveMassesInProfileOrder) {
  ASSERT_EQ(hugin.points.size(), 4u);
  ASSERT_EQ(hugin.points[0].name, "fore_starboard");
  // The line: fs, fp, as, ap are the initials of the profile's ids.
  const auto kg = installedFromLogHeader(withLine("fs=12.0 fp=12.0 as=9.6 ap=9.6"), hugin);
  ASSERT_TRUE(kg.has_value());
  EXPECT_EQ(*kg, (std::vector<double>{12.0, 12.0, 9.6, 9.6}));
  // Full ids, commas, a unit, in another order; an unnamed point is 0.
  const auto ids = installedFromLogHeader(withLine("aft_port=4.8kg, fore_starboard=2.4"), hugin);
  ASSERT_TRUE(ids.has_value());
  EXPECT_EQ(*ids, (std::vector<double>{2.4, 0.0, 0.0, 4.8}));
}

TEST_F(InstalledFromLog, OtherLinesAreNotMasses) {
  EXPECT_FALSE(installedFromLogHeader(MissionLog{}, hugin).has_value());                  // no line
  EXPECT_FALSE(installedFromLogHeader(withLine("1-2-3"), hugin).has_value());             // a configuration ID
  EXPECT_FALSE(installedFromLogHeader(withLine("fs=12 xx=3"), hugin).has_value());        // a point this vehicle lacks
  EXPECT_FALSE(installedFromLogHeader(withLine("fs=twelve"), hugin).has_value());         // not a number
}

}  // namespace auv::ui
