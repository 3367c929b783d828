#include "sim/water_column.h"

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "common/units.h"
#include "seawater/seawater.h"

namespace auv::sim {
namespace {

TEST(WaterColumn, UniformHasHydrostaticPressure) {
  const WaterColumn w = WaterColumn::uniform(1000.0, 12.0, 0.0);
  const WaterSample s = w.at(10.0);
  EXPECT_DOUBLE_EQ(s.density_kgm3, 1000.0);
  EXPECT_DOUBLE_EQ(s.temperature_degC, 12.0);
  EXPECT_NEAR(s.pressure_dbar, 1000.0 * units::g0 * 10.0 / 1e4, 1e-12);
  EXPECT_DOUBLE_EQ(w.at(-1.0).pressure_dbar, 0.0);
  EXPECT_THROW((void)WaterColumn::uniform(10.0), InputError);
}

TEST(WaterColumn, CastUsesEos80WithPressureAtTheGridPoints) {
  const std::vector<CtdPoint> cast = {{0.0, 15.0, 34.0}, {100.0, 8.0, 35.0}, {500.0, 4.0, 35.1}};
  const WaterColumn w = WaterColumn::fromCast(cast, 600.0, 1.0);
  for (double z : {0.0, 37.0, 100.0, 250.0, 600.0}) {
    const WaterSample s = w.at(z);
    const double p = seawater::pressureFromDepth(z);
    EXPECT_NEAR(s.pressure_dbar, p, 1e-9) << z;
    EXPECT_NEAR(s.density_kgm3, seawater::density(s.salinity_psu, s.temperature_degC, p), 1e-9) << z;
  }
  EXPECT_NEAR(w.at(50.0).temperature_degC, 11.5, 1e-12);  // linear between levels
  EXPECT_NEAR(w.at(50.0).salinity_psu, 34.5, 1e-12);
  // Between grid points density is interpolated; 1 m grid keeps it within 1 g/m^3.
  const double z = 123.4;
  const double p = seawater::pressureFromDepth(z);
  const WaterSample s = w.at(z);
  EXPECT_NEAR(s.density_kgm3, seawater::density(s.salinity_psu, s.temperature_degC, p), 1e-3);
  // Density increases with depth (pressure) in a uniform cast.
  const std::vector<CtdPoint> flat = {{0.0, 10.0, 35.0}};
  const WaterColumn u = WaterColumn::fromCast(flat, 1000.0, 5.0);
  EXPECT_GT(u.at(1000.0).density_kgm3 - u.at(0.0).density_kgm3, 4.0);
}

TEST(WaterColumn, RejectsUnsortedCast) {
  const std::vector<CtdPoint> cast = {{0.0, 15.0, 34.0}, {0.0, 8.0, 35.0}};
  EXPECT_THROW((void)WaterColumn::fromCast(cast, 100.0), InputError);
}

}  // namespace
}  // namespace auv::sim
