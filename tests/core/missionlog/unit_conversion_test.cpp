#include "missionlog/unit_conversion.h"

#include <gtest/gtest.h>

#include <numbers>

namespace auv {
namespace {
double conv(std::string_view from, std::string_view to, double v) {
  const auto c = unitConversion(from, to);
  EXPECT_TRUE(c.has_value()) << from << " -> " << to;
  return c ? c->apply(v) : 0.0;
}
}  // namespace

TEST(UnitConversion, CanonicalUnitsFollowTheFormatTable) {
  EXPECT_EQ(canonicalUnitFor("time"), "s");
  EXPECT_EQ(canonicalUnitFor("depth"), "m");
  EXPECT_EQ(canonicalUnitFor("battery_position"), "mm");
  EXPECT_EQ(canonicalUnitFor("pump_volume"), "cm3");
  EXPECT_EQ(canonicalUnitFor("pressure"), "dbar");
  EXPECT_EQ(canonicalUnitFor("conductivity"), "S/m");
  EXPECT_EQ(canonicalUnitFor("prop_rpm"), "rpm");
  // Variants take their base column's unit; unlisted columns keep their own.
  EXPECT_EQ(canonicalUnitFor("heading_cmd"), "deg");
  EXPECT_EQ(canonicalUnitFor("pump_volume_cmd"), "cm3");
  EXPECT_EQ(canonicalUnitFor("speed_flightmodel"), "m/s");
  EXPECT_EQ(canonicalUnitFor("depth_rate"), "");
  EXPECT_EQ(canonicalUnitFor("internal_pressure"), "");
  EXPECT_EQ(canonicalUnitFor("pressure_nav"), "");
  EXPECT_EQ(canonicalUnitFor("time_cmd"), "");
  EXPECT_EQ(baseChannelName("roll_mass_cmd"), "roll_mass");
}

TEST(UnitConversion, AnglesPressuresSpeedsAgainstDefinitions) {
  EXPECT_NEAR(conv("rad", "deg", std::numbers::pi), 180.0, 1e-12);
  EXPECT_NEAR(conv("mrad", "deg", 1000.0), 180.0 / std::numbers::pi, 1e-12);
  EXPECT_DOUBLE_EQ(conv("bar", "dbar", 1.0), 10.0);
  EXPECT_DOUBLE_EQ(conv("Pa", "dbar", 1e4), 1.0);
  EXPECT_DOUBLE_EQ(conv("kPa", "dbar", 101.325), 10.1325);
  EXPECT_NEAR(conv("psi", "dbar", 1.0), 6894.757293168361 / 1e4, 1e-15);  // NIST SP 811
  EXPECT_DOUBLE_EQ(conv("dbar", "dbar", 3.7), 3.7);
  EXPECT_NEAR(conv("knots", "m/s", 1.0), 1852.0 / 3600.0, 1e-15);  // 0.514444 m/s
  EXPECT_NEAR(conv("kn", "m/s", 3600.0), 1852.0, 1e-9);
  EXPECT_DOUBLE_EQ(conv("cm/s", "m/s", 25.0), 0.25);
  EXPECT_NEAR(conv("rad/s", "rpm", 2.0 * std::numbers::pi), 60.0, 1e-12);
}

TEST(UnitConversion, TemperaturesConductivityVolumesLengths) {
  EXPECT_NEAR(conv("degF", "degC", 212.0), 100.0, 1e-12);
  EXPECT_NEAR(conv("degF", "degC", 32.0), 0.0, 1e-12);
  EXPECT_NEAR(conv("degF", "degC", -40.0), -40.0, 1e-12);
  EXPECT_NEAR(conv("K", "degC", 273.15), 0.0, 1e-12);
  EXPECT_NEAR(conv("\xC2\xB0" "C", "degC", 12.5), 12.5, 0.0);
  // PSS-78 reference: C(35, 15 degC, 0) = 42.914 mS/cm = 4.2914 S/m.
  EXPECT_NEAR(conv("mS/cm", "S/m", 42.914), 4.2914, 1e-12);
  EXPECT_NEAR(conv("uS/cm", "S/m", 1e4), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(conv("l", "cm3", 0.25), 250.0);
  EXPECT_DOUBLE_EQ(conv("cc", "cm3", 233.0), 233.0);
  EXPECT_NEAR(conv("in", "mm", 1.0), 25.4, 1e-12);  // Slocum m_battpos
  EXPECT_NEAR(conv("ft", "m", 100.0), 30.48, 1e-12);
  EXPECT_DOUBLE_EQ(conv("kW", "W", 0.5), 500.0);
  EXPECT_DOUBLE_EQ(conv("ms", "s", 1500.0), 1.5);
  EXPECT_DOUBLE_EQ(conv("1", "PSU", 35.0), 35.0);  // CF writes practical salinity as "1"
}

TEST(UnitConversion, DifferentQuantitiesOrUnknownUnitsDoNotConvert) {
  EXPECT_FALSE(unitConversion("deg", "m"));
  EXPECT_FALSE(unitConversion("m", "dbar"));  // depth is not pressure
  EXPECT_FALSE(unitConversion("g/kg", "PSU"));  // absolute salinity is another quantity
  EXPECT_FALSE(unitConversion("furlong", "m"));
  EXPECT_FALSE(unitConversion("", "m"));
  EXPECT_TRUE(isKnownUnit("inHg"));
  EXPECT_FALSE(isKnownUnit("kg/m3"));
  const auto deg = unitsConvertibleTo("deg");
  EXPECT_NE(std::find(deg.begin(), deg.end(), "rad"), deg.end());
}

}  // namespace auv
