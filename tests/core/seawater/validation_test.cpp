#include "seawater/validation.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

#include "common/input_error.h"
#include "seawater/seawater.h"

namespace auv::seawater {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Runs f, expects an InputError for `field` whose message states `range`.
void expectRejected(const std::function<void()>& f, const std::string& field,
                    const std::string& range) {
  try {
    f();
    ADD_FAILURE() << field << ": no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field);
    EXPECT_NE(std::string(e.what()).find(range), std::string::npos) << e.what();
  }
}

TEST(SeawaterValidation, OutOfRangeNamesFieldAndRange) {
  expectRejected([] { density(42.5, 10, 0); }, "salinity_psu", "0 .. 42 psu");
  expectRejected([] { density(-0.1, 10, 0); }, "salinity_psu", "0 .. 42 psu");
  expectRejected([] { density(35, -2.5, 0); }, "temperature_degC", "-2 .. 40 degC");
  expectRejected([] { density(35, 40.5, 0); }, "temperature_degC", "-2 .. 40 degC");
  expectRejected([] { density(35, 10, -1); }, "pressure_dbar", "0 .. 11000 dbar");
  expectRejected([] { secantBulkModulus(35, 10, 11001); }, "pressure_dbar", "0 .. 11000 dbar");
  expectRejected([] { densityAtSurface(43, 10); }, "salinity_psu", "0 .. 42 psu");
  expectRejected([] { depthFromPressure(100, 91); }, "latitude_deg", "-90 .. 90 deg");
  expectRejected([] { pressureFromDepth(-0.5); }, "depth_m", "0 .. 10600 m");
  expectRejected([] { densityAtDepth(35, 10, 10601); }, "depth_m", "0 .. 10600 m");
  expectRejected([] { salinityFromConductivity(-0.1, 10, 0); }, "conductivity_Sm", "0 .. 10 S/m");
  expectRejected([] { conductivityFromSalinity(1.5, 10, 0); }, "salinity_psu", "2 .. 42 psu");
}

TEST(SeawaterValidation, NaNAndInfinityAreRejected) {
  expectRejected([] { density(kNaN, 10, 0); }, "salinity_psu", "not a number");
  expectRejected([] { density(35, kNaN, 0); }, "temperature_degC", "not a number");
  expectRejected([] { density(35, 10, kNaN); }, "pressure_dbar", "not a number");
  expectRejected([] { depthFromPressure(100, kNaN); }, "latitude_deg", "not a number");
  expectRejected([] { salinityFromConductivity(kNaN, 10, 0); }, "conductivity_Sm", "not a number");
  expectRejected([] { density(35, 10, std::numeric_limits<double>::infinity()); }, "pressure_dbar",
                 "0 .. 11000 dbar");
}

TEST(SeawaterValidation, RangeEndsAreAccepted) {
  EXPECT_NO_THROW(density(0, -2, 0));
  EXPECT_NO_THROW(density(42, 40, 11000));
  EXPECT_NO_THROW(depthFromPressure(11000, -90));
  // The depth limit is chosen so its pressure stays inside the EOS-80 range
  // at every latitude.
  EXPECT_NO_THROW(densityAtDepth(35, 2, 10600, 90));
  EXPECT_LE(pressureFromDepth(10600, 90), 11000.0);
}

}  // namespace
}  // namespace auv::seawater
