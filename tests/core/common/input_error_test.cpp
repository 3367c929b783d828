#include "common/input_error.h"

#include <gtest/gtest.h>

#include "common/units.h"

namespace auv {

TEST(InputError, MessageNamesFileLineColumnFieldAndFix) {
  InputError e("depth", "not a number", "write metres", {"log.csv", 12, 3});
  EXPECT_STREQ(e.what(), "log.csv:12:3: depth: not a number; write metres");
  EXPECT_EQ(e.where().line, 12);
}

TEST(InputError, WithoutFileThereIsNoLocationPrefix) {
  InputError e("salinity", "missing", "give --salinity PSU");
  EXPECT_STREQ(e.what(), "salinity: missing; give --salinity PSU");
}

TEST(Units, ConversionsRoundTrip) {
  EXPECT_DOUBLE_EQ(units::radToDeg(units::degToRad(37.5)), 37.5);
  EXPECT_DOUBLE_EQ(units::kgfToNewton(1.0), 9.80665);
  EXPECT_DOUBLE_EQ(units::barToDbar(1.0), 10.0);
  EXPECT_DOUBLE_EQ(units::dbarToPa(1.0), 1e4);
}

}  // namespace auv
