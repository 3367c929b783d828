#include "missionlog/iso8601.h"

#include <gtest/gtest.h>

namespace auv {

TEST(Iso8601, KnownInstantsAgainstUnixTime) {
  // Reference values: `date -u -d ... +%s`.
  EXPECT_DOUBLE_EQ(*parseIso8601("1970-01-01T00:00:00Z"), 0.0);
  EXPECT_DOUBLE_EQ(*parseIso8601("2000-01-01T00:00:00Z"), 946684800.0);
  EXPECT_DOUBLE_EQ(*parseIso8601("2026-05-14T08:12:00Z"), 1778746320.0);
  EXPECT_DOUBLE_EQ(*parseIso8601("2024-02-29T12:00:00Z"), 1709208000.0);  // leap day
  EXPECT_NEAR(*parseIso8601("2016-06-23T17:51:11.771Z"), 1466704271.771, 1e-6);
  EXPECT_DOUBLE_EQ(*parseIso8601("1969-12-31T23:59:59Z"), -1.0);
}

TEST(Iso8601, ZonesSeparatorsAndDateOnly) {
  const double utc = *parseIso8601("2026-05-14T08:12:00Z");
  EXPECT_DOUBLE_EQ(*parseIso8601("2026-05-14T10:12:00+02:00"), utc);
  EXPECT_DOUBLE_EQ(*parseIso8601("2026-05-14T05:42:00-0230"), utc);
  EXPECT_DOUBLE_EQ(*parseIso8601("2026-05-14 08:12:00"), utc);  // no zone = UTC
  EXPECT_DOUBLE_EQ(*parseIso8601("2026-05-14T08:12Z"), utc);
  EXPECT_DOUBLE_EQ(*parseIso8601("2026-05-14"), utc - (8 * 3600 + 12 * 60));
}

TEST(Iso8601, RejectsImpossibleOrPartialTimes) {
  EXPECT_FALSE(parseIso8601("2023-02-29T00:00:00Z"));  // not a leap year
  EXPECT_FALSE(parseIso8601("2026-13-01T00:00:00Z"));
  EXPECT_FALSE(parseIso8601("2026-05-14T24:00:00Z"));
  EXPECT_FALSE(parseIso8601("2026-05-14T08:60:00Z"));
  EXPECT_FALSE(parseIso8601("2026-05-14T08:12:00Zjunk"));
  EXPECT_FALSE(parseIso8601("14/05/2026 08:12:00"));
  EXPECT_FALSE(parseIso8601("2026-05-14T08:12:00."));
  EXPECT_FALSE(parseIso8601(""));
}

TEST(Iso8601, FormatRoundTripsToTheMillisecond) {
  EXPECT_EQ(formatIso8601(1778746320.0), "2026-05-14T08:12:00.000Z");
  EXPECT_EQ(formatIso8601(1466704271.771), "2016-06-23T17:51:11.771Z");
  EXPECT_EQ(formatIso8601(59.9996, 3), "1970-01-01T00:01:00.000Z");
  EXPECT_EQ(formatIso8601(-1.0, 0), "1969-12-31T23:59:59Z");
  EXPECT_NEAR(*parseIso8601(formatIso8601(1709208000.125)), 1709208000.125, 1e-6);
}

}  // namespace auv
