// The small pieces the vendor readers share: unit spellings, header cells,
// dates and CF time units. Oracles: the ISO 8601 parser of iso8601.h (an
// independent implementation), calendar facts, and the CF convention text.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "missionlog/channel_aliases.h"
#include "missionlog/iso8601.h"
#include "missionlog/time_text.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"

namespace auv {
namespace {

double iso(const char* s) { return *parseIso8601(s); }

TEST(UnitSpelling, VendorSpellingsReachTheConversionTable) {
  EXPECT_EQ(normaliseUnitSpelling("degc"), "degC");        // dbd2asc
  EXPECT_EQ(normaliseUnitSpelling("s/m"), "S/m");          // dbd2asc
  EXPECT_EQ(normaliseUnitSpelling("S m-1"), "S/m");        // CF
  EXPECT_EQ(normaliseUnitSpelling("mS cm-1"), "mS/cm");    // CF
  EXPECT_EQ(normaliseUnitSpelling("nodim"), "1");
  EXPECT_EQ(normaliseUnitSpelling("degrees_C"), "degC");
  EXPECT_EQ(normaliseUnitSpelling("degree_Celsius"), "degree_Celsius");  // already known as written
  EXPECT_EQ(normaliseUnitSpelling("degrees_north"), "deg");
  EXPECT_EQ(normaliseUnitSpelling(" DBAR "), "dbar");       // case and blanks
  EXPECT_EQ(normaliseUnitSpelling("RAD"), "rad");
  EXPECT_EQ(normaliseUnitSpelling("MS/CM"), "mS/cm");
  EXPECT_EQ(normaliseUnitSpelling("kg m-3"), "kg/m3");
  EXPECT_EQ(normaliseUnitSpelling("1e-3"), "PSU");          // old CF salinity
  EXPECT_EQ(normaliseUnitSpelling("furlongs"), "furlongs");  // unknown: unchanged
  EXPECT_EQ(normaliseUnitSpelling("Pa"), "Pa");             // exact spelling wins
  // The normalised spellings convert: 35 mS/cm = 3.5 S/m, 1 bar = 10 dbar.
  EXPECT_DOUBLE_EQ(unitConversion(normaliseUnitSpelling("mS cm-1"), "S/m")->apply(35.0), 3.5);
  EXPECT_DOUBLE_EQ(unitConversion(normaliseUnitSpelling("bar"), "dbar")->apply(0.612), 6.12);
}

struct HeaderCase {
  const char* cell;
  const char* name;
  const char* unit;
  const char* key;
};

TEST(HeaderField, UnitsInBracketsParenthesesSlashesAndSuffixes) {
  const HeaderCase cases[] = {
      {"Depth(m)", "Depth", "m", "depth"},
      {"depth_m", "depth", "m", "depth"},
      {"DEPTH [m]", "DEPTH", "m", "depth"},
      {"m_depth", "m_depth", "", "m_depth"},
      {"PITCH (rad)", "PITCH", "rad", "pitch"},
      {"pitch_cmd_deg", "pitch_cmd", "deg", "pitch_cmd"},
      {"Depth cmd / m", "Depth cmd", "m", "depth_cmd"},
      {"\"Speed {kn}\"", "Speed", "kn", "speed"},
      {"Water Depth (ft)", "Water Depth", "ft", "water_depth"},
      {"water_depth_m", "water_depth_m", "", "water_depth_m"},  // water_depth is no known channel
      {"Temp (\xC2\xB0" "C)", "Temp", "\xC2\xB0" "C", "temp"},
      {"  time_s ", "time", "s", "time"},
  };
  for (const auto& c : cases) {
    const HeaderField f = parseHeaderField(c.cell);
    EXPECT_EQ(f.name, c.name) << c.cell;
    EXPECT_EQ(f.unit, c.unit) << c.cell;
    EXPECT_EQ(f.key, c.key) << c.cell;
  }
}

TEST(ChannelAlias, GenericAndSlocumNamesMapToTheFormatChannels) {
  EXPECT_EQ(findChannelAlias("m_depth")->channel, "depth");
  EXPECT_EQ(findChannelAlias("m_depth")->unit, "m");
  EXPECT_EQ(findChannelAlias("m_pitch")->unit, "rad");  // Slocum masterdata unit
  EXPECT_EQ(findChannelAlias("sci_water_temp")->channel, "temperature");
  EXPECT_EQ(findChannelAlias("sci_water_pressure")->unit, "bar");
  EXPECT_EQ(findChannelAlias("m_battpos")->channel, "battery_position");
  EXPECT_EQ(findChannelAlias("m_de_oil_vol")->channel, "pump_volume");
  EXPECT_EQ(findChannelAlias("m_ballast_pumped")->channel, "pump_volume");
  EXPECT_EQ(findChannelAlias("m_fin")->channel, "rudder");
  EXPECT_EQ(findChannelAlias("commanded_depth")->channel, "depth_cmd");
  EXPECT_EQ(findChannelAlias("rpm")->channel, "prop_rpm");
  EXPECT_EQ(findChannelAlias("pitch")->channel, "pitch");       // format names map to themselves
  EXPECT_EQ(findChannelAlias("heading_cmd")->channel, "heading_cmd");
  EXPECT_EQ(findChannelAlias("m_present_time")->channel, "time");
  EXPECT_FALSE(findChannelAlias("m_vacuum").has_value());       // kept under its own name
  EXPECT_EQ(normaliseChannelKey("  Water--Temp. (x) "), "water_temp_(x)");
}

TEST(TimeText, DayMonthYearAgreesWithIso8601) {
  EXPECT_EQ(*parseDayMonthYear("14.05.2026 08:12:00"), iso("2026-05-14T08:12:00Z"));
  EXPECT_EQ(*parseDayMonthYear("14.05.2026 08:12:00,5"), iso("2026-05-14T08:12:00.5Z"));
  EXPECT_EQ(*parseDayMonthYear("1.5.2026 8:12:03.25"), iso("2026-05-01T08:12:03.25Z"));
  EXPECT_EQ(*parseDayMonthYear("29.02.2024"), iso("2024-02-29T00:00:00Z"));  // leap year
  EXPECT_FALSE(parseDayMonthYear("29.02.2023"));                              // not one
  EXPECT_FALSE(parseDayMonthYear("31.04.2026 00:00"));
  EXPECT_FALSE(parseDayMonthYear("14.05.2026 25:00"));
  EXPECT_FALSE(parseDayMonthYear("14/05/2026 08:12"));
  EXPECT_EQ(*parseDateOnly("2026-05-14"), iso("2026-05-14T00:00:00Z"));
  EXPECT_EQ(*parseTimeOfDay("08:12:03.25"), 8 * 3600 + 12 * 60 + 3.25);
  EXPECT_FALSE(parseTimeOfDay("8:5"));
  EXPECT_EQ(*civilDays(1970, 1, 1), 0);
  EXPECT_EQ(*civilDays(2000, 3, 1), 11017);  // 30 years incl. 7 leap days + Jan/Feb 2000
}

TEST(TimeText, CfTimeUnits) {
  auto a = parseCfTimeUnits("seconds since 1970-01-01T00:00:00Z");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->scale, 1.0);
  EXPECT_EQ(a->offset, 0.0);
  auto b = parseCfTimeUnits("seconds since 1970-1-1 00:00:00");  // Seaglider basestation
  ASSERT_TRUE(b);
  EXPECT_EQ(b->offset, 0.0);
  // Argo's JULD: 1950 -> 1970 is 20 years with 5 leap days = 7305 days.
  auto c = parseCfTimeUnits("days since 1950-01-01T00:00:00Z");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->scale, 86400.0);
  EXPECT_EQ(c->offset, -7305.0 * 86400.0);
  auto d = parseCfTimeUnits("hours since 2024-05-27 09:05:16 +02:00");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->scale, 3600.0);
  EXPECT_EQ(d->offset, iso("2024-05-27T07:05:16Z"));
  auto e = parseCfTimeUnits("milliseconds since 2020-09-08 UTC");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->offset, iso("2020-09-08T00:00:00Z"));
  EXPECT_FALSE(parseCfTimeUnits("seconds"));
  EXPECT_FALSE(parseCfTimeUnits("fortnights since 1970-01-01"));
  EXPECT_FALSE(parseCfTimeUnits("seconds since 1970-13-01"));
  EXPECT_FALSE(parseCfTimeUnits("seconds since 1970-01-01 00:00:00 CEST"));
}

}  // namespace
}  // namespace auv
