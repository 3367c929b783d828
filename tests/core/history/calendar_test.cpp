// Timestamps, configuration IDs and the temperature staleness rule.
#include <gtest/gtest.h>

#include <ctime>

#include "common/input_error.h"
#include "history/configuration_id.h"
#include "history/staleness.h"
#include "history/timestamp.h"

namespace auv {
using namespace std::chrono;

TEST(Timestamp, IsoRoundTripAndKnownEpoch) {
  // 2014-04-04T15:28:00Z is 1396625280 s after the Unix epoch (date -u -d ... +%s).
  const TimePoint t = makeUtc(2014, 4, 4, 15, 28, 0);
  EXPECT_EQ(t.time_since_epoch().count(), 1396625280);
  EXPECT_EQ(toIsoUtc(t), "2014-04-04T15:28:00Z");
  EXPECT_EQ(parseIsoUtc("2014-04-04T15:28:00Z"), t);
  EXPECT_EQ(toIsoUtc(makeUtc(2024, 2, 29, 23, 59, 59)), "2024-02-29T23:59:59Z");
}

TEST(Timestamp, RejectsWhatWeNeverWrite) {
  EXPECT_THROW(parseIsoUtc("2014-04-04 15:28:00"), InputError);
  EXPECT_THROW(parseIsoUtc("2014-04-04T15:28:00+02"), InputError);
  EXPECT_THROW(parseIsoUtc("2023-02-29T00:00:00Z"), InputError);  // not a leap year
  EXPECT_THROW(parseIsoUtc("2014-13-01T00:00:00Z"), InputError);
  EXPECT_THROW(makeUtc(2014, 4, 31), InputError);
}

TEST(ConfigurationId, ThesisExamplesAndRejects) {
  // Fig. 5.14 and Fig. 7.9 use these IDs; "xx-xx-xx" in §5.5.1.
  EXPECT_TRUE(isValidConfigurationId("1-2-3"));
  EXPECT_TRUE(isValidConfigurationId("sys-0-0"));
  EXPECT_TRUE(isValidConfigurationId("01-02-03"));
  EXPECT_TRUE(isValidConfigurationId("HUGIN-PL7-OSLO"));
  EXPECT_FALSE(isValidConfigurationId(""));
  EXPECT_FALSE(isValidConfigurationId("1-2"));
  EXPECT_FALSE(isValidConfigurationId("1-2-3-4"));
  EXPECT_FALSE(isValidConfigurationId("1--3"));
  EXPECT_FALSE(isValidConfigurationId("1-2-"));
  EXPECT_FALSE(isValidConfigurationId("1 -2-3"));
  EXPECT_FALSE(isValidConfigurationId("123456789-1-1"));  // group > 8
  try {
    requireValidConfigurationId("12/34/56");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("12/34/56"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("xx-xx-xx"), std::string::npos);
  }
}

TEST(Staleness, MonthEndsClampAndLeapYears) {
  EXPECT_EQ(addOneCalendarMonth(makeUtc(2023, 1, 31, 10)), makeUtc(2023, 2, 28, 10));
  EXPECT_EQ(addOneCalendarMonth(makeUtc(2024, 1, 31, 10)), makeUtc(2024, 2, 29, 10));
  EXPECT_EQ(addOneCalendarMonth(makeUtc(2100, 1, 29)), makeUtc(2100, 2, 28));  // 2100 not leap
  EXPECT_EQ(addOneCalendarMonth(makeUtc(2000, 1, 30)), makeUtc(2000, 2, 29));  // 2000 is leap
  EXPECT_EQ(addOneCalendarMonth(makeUtc(2014, 3, 31, 8, 15)), makeUtc(2014, 4, 30, 8, 15));
  EXPECT_EQ(addOneCalendarMonth(makeUtc(2014, 12, 15, 23, 59, 59)), makeUtc(2015, 1, 15, 23, 59, 59));
  EXPECT_EQ(addOneCalendarMonth(makeUtc(2024, 2, 29)), makeUtc(2024, 3, 29));
}

// Independent oracle: the C library's timegm() normalises month overflow;
// "day 0 of month m+2" is the last day of month m+1. So one calendar month
// later, clamped, is min(timegm(y, m+1, d), timegm(y, m+2, 0)) for every day.
TEST(Staleness, AgreesWithTimegmForEveryDay2000To2030) {
  auto cTime = [](int y, int mon0, int d, int h) {
    std::tm tm{};
    tm.tm_year = y - 1900;
    tm.tm_mon = mon0;
    tm.tm_mday = d;
    tm.tm_hour = h;
    return TimePoint{seconds{timegm(&tm)}};
  };
  int checked = 0;
  for (TimePoint t = makeUtc(2000, 1, 1, 13); t < makeUtc(2031, 1, 1); t += days{1}) {
    const year_month_day ymd{floor<days>(t)};
    const int y = int(ymd.year()), m0 = int(unsigned(ymd.month())) - 1, d = int(unsigned(ymd.day()));
    const TimePoint expected = std::min(cTime(y, m0 + 1, d, 13), cTime(y, m0 + 2, 0, 13));
    ASSERT_EQ(addOneCalendarMonth(t), expected) << toIsoUtc(t);
    ++checked;
  }
  EXPECT_EQ(checked, 11323);  // days from 2000-01-01 to 2030-12-31
}

TEST(Staleness, ExactlyOneMonthMayBeReusedOneSecondMoreMayNot) {
  // App. B comments: "equal or less than a month" -> reuse; "more than a month" -> new.
  const TimePoint measured = makeUtc(2014, 5, 19, 20, 32);
  EXPECT_FALSE(temperatureIsStale(measured, makeUtc(2014, 5, 20, 12, 19)));
  EXPECT_FALSE(temperatureIsStale(measured, makeUtc(2014, 6, 19, 20, 32)));
  EXPECT_TRUE(temperatureIsStale(measured, makeUtc(2014, 6, 19, 20, 32, 1)));
  // Jan 31 -> stale after Feb 28 (2023) but only after Feb 29 in 2024.
  EXPECT_TRUE(temperatureIsStale(makeUtc(2023, 1, 31), makeUtc(2023, 2, 28, 0, 0, 1)));
  EXPECT_FALSE(temperatureIsStale(makeUtc(2024, 1, 31), makeUtc(2024, 2, 28, 0, 0, 1)));
  EXPECT_TRUE(temperatureIsStale(makeUtc(2024, 1, 31), makeUtc(2024, 2, 29, 0, 0, 1)));
  // A measurement time in the future means a wrong clock: ask again.
  EXPECT_TRUE(temperatureIsStale(makeUtc(2014, 5, 20), makeUtc(2014, 5, 19)));
}

}  // namespace auv
