#include "missionlog/unit_conversion.h"

#include <array>
#include <numbers>

namespace auv {
namespace {

enum class Quantity { kAngle, kLength, kPressure, kTemperature, kSpeed, kConductivity,
                      kSalinity, kVolume, kRotation, kPower, kTime, kDimensionless };

// value_in_base = value * factor + offset; the base of each quantity is the
// format's canonical unit where the table has one (length: m).
struct UnitDef {
  std::string_view spelling;
  Quantity quantity;
  double factor;
  double offset;
};

constexpr double kPi = std::numbers::pi;

// Pressures are sea (gauge) pressures: a file in bar or psi is assumed to
// already have the atmosphere removed, as the format defines `pressure`.
constexpr std::array kUnits = {
    UnitDef{"deg", Quantity::kAngle, 1.0, 0.0},
    UnitDef{"degree", Quantity::kAngle, 1.0, 0.0},
    UnitDef{"degrees", Quantity::kAngle, 1.0, 0.0},
    UnitDef{"\xC2\xB0", Quantity::kAngle, 1.0, 0.0},  // °
    UnitDef{"rad", Quantity::kAngle, 180.0 / kPi, 0.0},
    UnitDef{"radian", Quantity::kAngle, 180.0 / kPi, 0.0},
    UnitDef{"radians", Quantity::kAngle, 180.0 / kPi, 0.0},
    UnitDef{"mrad", Quantity::kAngle, 0.18 / kPi, 0.0},

    UnitDef{"m", Quantity::kLength, 1.0, 0.0},
    UnitDef{"metre", Quantity::kLength, 1.0, 0.0},
    UnitDef{"meter", Quantity::kLength, 1.0, 0.0},
    UnitDef{"metres", Quantity::kLength, 1.0, 0.0},
    UnitDef{"meters", Quantity::kLength, 1.0, 0.0},
    UnitDef{"mm", Quantity::kLength, 1e-3, 0.0},
    UnitDef{"cm", Quantity::kLength, 1e-2, 0.0},
    UnitDef{"km", Quantity::kLength, 1e3, 0.0},
    UnitDef{"in", Quantity::kLength, 0.0254, 0.0},
    UnitDef{"inch", Quantity::kLength, 0.0254, 0.0},
    UnitDef{"ft", Quantity::kLength, 0.3048, 0.0},

    UnitDef{"dbar", Quantity::kPressure, 1.0, 0.0},
    UnitDef{"decibar", Quantity::kPressure, 1.0, 0.0},
    UnitDef{"bar", Quantity::kPressure, 10.0, 0.0},
    UnitDef{"mbar", Quantity::kPressure, 0.01, 0.0},
    UnitDef{"hPa", Quantity::kPressure, 0.01, 0.0},
    UnitDef{"Pa", Quantity::kPressure, 1e-4, 0.0},
    UnitDef{"kPa", Quantity::kPressure, 0.1, 0.0},
    UnitDef{"MPa", Quantity::kPressure, 100.0, 0.0},
    UnitDef{"psi", Quantity::kPressure, 0.6894757293168361, 0.0},  // 6894.757... Pa (NIST SP 811)
    UnitDef{"inHg", Quantity::kPressure, 0.338638866667, 0.0},      // 3386.38866667 Pa at 0 degC
    UnitDef{"atm", Quantity::kPressure, 10.1325, 0.0},

    UnitDef{"degC", Quantity::kTemperature, 1.0, 0.0},
    UnitDef{"\xC2\xB0" "C", Quantity::kTemperature, 1.0, 0.0},  // °C
    UnitDef{"C", Quantity::kTemperature, 1.0, 0.0},
    UnitDef{"deg C", Quantity::kTemperature, 1.0, 0.0},
    UnitDef{"Celsius", Quantity::kTemperature, 1.0, 0.0},
    UnitDef{"degree_Celsius", Quantity::kTemperature, 1.0, 0.0},
    UnitDef{"degrees_Celsius", Quantity::kTemperature, 1.0, 0.0},
    UnitDef{"degF", Quantity::kTemperature, 5.0 / 9.0, -160.0 / 9.0},
    UnitDef{"\xC2\xB0" "F", Quantity::kTemperature, 5.0 / 9.0, -160.0 / 9.0},  // °F
    UnitDef{"F", Quantity::kTemperature, 5.0 / 9.0, -160.0 / 9.0},
    UnitDef{"K", Quantity::kTemperature, 1.0, -273.15},
    UnitDef{"kelvin", Quantity::kTemperature, 1.0, -273.15},

    UnitDef{"m/s", Quantity::kSpeed, 1.0, 0.0},
    UnitDef{"m s-1", Quantity::kSpeed, 1.0, 0.0},
    UnitDef{"cm/s", Quantity::kSpeed, 0.01, 0.0},
    UnitDef{"mm/s", Quantity::kSpeed, 1e-3, 0.0},
    UnitDef{"km/h", Quantity::kSpeed, 1.0 / 3.6, 0.0},
    UnitDef{"knots", Quantity::kSpeed, 1852.0 / 3600.0, 0.0},  // international knot
    UnitDef{"knot", Quantity::kSpeed, 1852.0 / 3600.0, 0.0},
    UnitDef{"kn", Quantity::kSpeed, 1852.0 / 3600.0, 0.0},
    UnitDef{"kt", Quantity::kSpeed, 1852.0 / 3600.0, 0.0},
    UnitDef{"kts", Quantity::kSpeed, 1852.0 / 3600.0, 0.0},

    UnitDef{"S/m", Quantity::kConductivity, 1.0, 0.0},
    UnitDef{"mS/cm", Quantity::kConductivity, 0.1, 0.0},
    UnitDef{"uS/cm", Quantity::kConductivity, 1e-4, 0.0},
    UnitDef{"\xC2\xB5S/cm", Quantity::kConductivity, 1e-4, 0.0},  // µS/cm
    UnitDef{"mS/m", Quantity::kConductivity, 1e-3, 0.0},

    UnitDef{"PSU", Quantity::kSalinity, 1.0, 0.0},
    UnitDef{"psu", Quantity::kSalinity, 1.0, 0.0},
    UnitDef{"PSS-78", Quantity::kSalinity, 1.0, 0.0},
    UnitDef{"pss-78", Quantity::kSalinity, 1.0, 0.0},

    UnitDef{"cm3", Quantity::kVolume, 1.0, 0.0},
    UnitDef{"cm^3", Quantity::kVolume, 1.0, 0.0},
    UnitDef{"cm\xC2\xB3", Quantity::kVolume, 1.0, 0.0},  // cm³
    UnitDef{"cc", Quantity::kVolume, 1.0, 0.0},
    UnitDef{"ml", Quantity::kVolume, 1.0, 0.0},
    UnitDef{"mL", Quantity::kVolume, 1.0, 0.0},
    UnitDef{"l", Quantity::kVolume, 1e3, 0.0},
    UnitDef{"L", Quantity::kVolume, 1e3, 0.0},
    UnitDef{"m3", Quantity::kVolume, 1e6, 0.0},
    UnitDef{"m^3", Quantity::kVolume, 1e6, 0.0},

    UnitDef{"rpm", Quantity::kRotation, 1.0, 0.0},
    UnitDef{"RPM", Quantity::kRotation, 1.0, 0.0},
    UnitDef{"rev/min", Quantity::kRotation, 1.0, 0.0},
    UnitDef{"rev/s", Quantity::kRotation, 60.0, 0.0},
    UnitDef{"Hz", Quantity::kRotation, 60.0, 0.0},
    UnitDef{"rad/s", Quantity::kRotation, 30.0 / kPi, 0.0},

    UnitDef{"W", Quantity::kPower, 1.0, 0.0},
    UnitDef{"mW", Quantity::kPower, 1e-3, 0.0},
    UnitDef{"kW", Quantity::kPower, 1e3, 0.0},

    UnitDef{"s", Quantity::kTime, 1.0, 0.0},
    UnitDef{"sec", Quantity::kTime, 1.0, 0.0},
    UnitDef{"seconds", Quantity::kTime, 1.0, 0.0},
    UnitDef{"ms", Quantity::kTime, 1e-3, 0.0},
    UnitDef{"min", Quantity::kTime, 60.0, 0.0},
    UnitDef{"h", Quantity::kTime, 3600.0, 0.0},

    UnitDef{"1", Quantity::kDimensionless, 1.0, 0.0},
};

struct TableEntry {
  std::string_view name;
  std::string_view unit;
};

// The column table of the format (mission-log-csv.md), plus time.
constexpr std::array kTable = {
    TableEntry{"time", "s"},          TableEntry{"depth", "m"},
    TableEntry{"depth_cmd", "m"},     TableEntry{"altitude", "m"},
    TableEntry{"pitch", "deg"},       TableEntry{"pitch_cmd", "deg"},
    TableEntry{"roll", "deg"},        TableEntry{"heading", "deg"},
    TableEntry{"speed", "m/s"},       TableEntry{"prop_rpm", "rpm"},
    TableEntry{"elevator", "deg"},    TableEntry{"rudder", "deg"},
    TableEntry{"temperature", "degC"}, TableEntry{"salinity", "PSU"},
    TableEntry{"conductivity", "S/m"}, TableEntry{"pressure", "dbar"},
    TableEntry{"pump_volume", "cm3"}, TableEntry{"battery_position", "mm"},
    TableEntry{"roll_mass", "deg"},   TableEntry{"power", "W"},
};

constexpr std::array<std::string_view, 3> kVariantSuffixes = {"_cmd", "_est", "_flightmodel"};

const UnitDef* lookup(std::string_view unit) {
  for (const auto& u : kUnits)
    if (u.spelling == unit) return &u;
  return nullptr;
}

}  // namespace

std::string_view baseChannelName(std::string_view channel) {
  for (auto suffix : kVariantSuffixes)
    if (channel.size() > suffix.size() && channel.ends_with(suffix))
      return channel.substr(0, channel.size() - suffix.size());
  return channel;
}

std::string_view canonicalUnitFor(std::string_view channel) {
  for (const auto& e : kTable)
    if (e.name == channel) return e.unit;
  const auto base = baseChannelName(channel);
  if (base != channel && base != "time")
    for (const auto& e : kTable)
      if (e.name == base) return e.unit;
  return {};
}

bool isKnownUnit(std::string_view unit) { return lookup(unit) != nullptr; }

std::optional<UnitConversion> unitConversion(std::string_view from, std::string_view to) {
  const UnitDef* a = lookup(from);
  const UnitDef* b = lookup(to);
  if (!a || !b) return std::nullopt;
  // Practical salinity is dimensionless; CF files write its unit as "1".
  const bool salinityAsOne = (a->quantity == Quantity::kDimensionless && b->quantity == Quantity::kSalinity);
  if (a->quantity != b->quantity && !salinityAsOne) return std::nullopt;
  if (salinityAsOne) return UnitConversion{};
  // base = v*fa + oa ; out = (base - ob) / fb
  UnitConversion c;
  c.scale = a->factor / b->factor;
  c.offset = (a->offset - b->offset) / b->factor;
  if (a == b || (a->factor == b->factor && a->offset == b->offset)) c = UnitConversion{};
  return c;
}

std::vector<std::string> unitsConvertibleTo(std::string_view canonical) {
  std::vector<std::string> out;
  const UnitDef* c = lookup(canonical);
  if (!c) return out;
  for (const auto& u : kUnits)
    if (u.quantity == c->quantity) out.emplace_back(u.spelling);
  return out;
}

}  // namespace auv
