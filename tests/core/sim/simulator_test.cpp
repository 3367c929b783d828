#include "sim/simulator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "sim/sensor_noise.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

using testing::Delphin2;

Scenario hover(double seconds, double depth = 1.0) {
  Scenario sc;
  sc.net_buoyancy_n = 6.0;
  sc.legs = {{seconds, depth, 0.0}};
  return sc;
}

TEST(GaussianSource, UnitVarianceAndSeedDeterminism) {
  GaussianSource a(42), b(42), c(43);
  double sum = 0.0, sum2 = 0.0;
  const int n = 200000;
  bool differs = false;
  for (int i = 0; i < n; ++i) {
    const double x = a.next();
    EXPECT_EQ(x, b.next());
    differs = differs || x != c.next();
    sum += x;
    sum2 += x * x;
  }
  EXPECT_TRUE(differs);
  // Mean within 4 sigma/sqrt(n), variance within 4 * sqrt(2/n).
  EXPECT_NEAR(sum / n, 0.0, 4.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 4.0 * std::sqrt(2.0 / n));
}

TEST(Simulator, TraceIsSampledOnTheRequestedGrid) {
  const Delphin2 d;
  const SimTrace tr = simulate(d.model, d.autopilot, WaterColumn::uniform(1000.0), hover(10.0));
  ASSERT_EQ(tr.size(), 51u);  // 0, 0.2, ..., 10 s
  for (std::size_t i = 0; i < tr.size(); ++i) EXPECT_NEAR(tr.time_s[i], 0.2 * static_cast<double>(i), 1e-9);
  EXPECT_EQ(tr.depth_m.size(), tr.size());
  EXPECT_EQ(tr.power_w.size(), tr.size());
  EXPECT_NEAR(tr.net_buoyancy_n.front(), 6.0, 1e-9);  // trimmed as asked
  // Whole-run energy is the integral of power: hotel alone is 30 W x 10 s.
  EXPECT_NEAR(tr.hotel_energy_j, 300.0, 1e-9);
}

TEST(Simulator, SameSeedSameRunOtherSeedOtherNoise) {
  const Delphin2 d;
  SimOptions opt;
  opt.noise.depth_m = 0.02;
  opt.noise.pitch_rad = 0.002;
  opt.noise.depth_rate_mps = 0.01;
  opt.seed = 11;
  const WaterColumn w = WaterColumn::uniform(1000.0);
  const SimTrace a = simulate(d.model, d.autopilot, w, hover(60.0), opt);
  const SimTrace b = simulate(d.model, d.autopilot, w, hover(60.0), opt);
  EXPECT_EQ(a.depth_m, b.depth_m);
  EXPECT_EQ(a.thruster_front_rpm, b.thruster_front_rpm);
  opt.seed = 12;
  const SimTrace c = simulate(d.model, d.autopilot, w, hover(60.0), opt);
  EXPECT_NE(a.depth_m, c.depth_m);
  // The logged depth carries the configured noise: against the noise-free
  // run (whose path differs by millimetres only) the scatter is sigma.
  const SimTrace clean = simulate(d.model, d.autopilot, w, hover(60.0));
  double sum2 = 0.0;
  for (std::size_t i = 0; i < clean.size(); ++i) sum2 += std::pow(a.depth_m[i] - clean.depth_m[i], 2);
  EXPECT_NEAR(std::sqrt(sum2 / static_cast<double>(clean.size())), 0.02, 0.003);
}

TEST(Simulator, BuoyancyChangeLandsAtItsTime) {
  const Delphin2 d;
  Scenario sc = hover(20.0);
  sc.buoyancy_changes = {{10.0, -3.0}};
  const SimTrace tr = simulate(d.model, d.autopilot, WaterColumn::uniform(1000.0), sc);
  EXPECT_NEAR(tr.net_buoyancy_n[49], 6.0, 1e-9);  // t = 9.8 s
  EXPECT_NEAR(tr.net_buoyancy_n[50], 3.0, 1e-9);  // t = 10 s
}

TEST(Simulator, CompressibleHullLosesBuoyancyWithPressure) {
  Delphin2 d;
  const double kappa = 3e-6;  // per dbar
  d.model.body.hull.compressibility_per_dbar = kappa;
  const double rho = 1000.0;
  const double B0 = rho * units::g0 * d.model.body.hull.volume_m3;
  Scenario sc;
  // Neutral at the surface via a trim mass at the CB, then start at 50 m.
  sc.extra_masses = {{B0 / units::g0 - d.model.body.mass_kg, Eigen::Vector3d::Zero()}};
  sc.initial_depth_m = 50.0;
  sc.legs = {{1.0, 50.0, 0.0}};
  const SimTrace tr = simulate(d.model, d.autopilot, WaterColumn::uniform(rho), sc);
  const double p = rho * units::g0 * 50.0 / 1e4;
  EXPECT_NEAR(tr.net_buoyancy_n.front(), -B0 * kappa * p, 1e-9);
  EXPECT_NEAR(tr.pressure_dbar.front(), p, 1e-12);
}

TEST(Simulator, SurfacedVehicleFloatsWhereWeightEqualsSubmergedBuoyancy) {
  const Delphin2 d;
  DepthAutopilotConfig off;  // all gains zero: no thrust
  SimOptions opt;
  opt.surface_model = true;
  opt.preload_hover_integrator = false;
  // Oracle: bisection on submergedFraction(z) = W / B for the 0.26 m hull.
  const double B = 1000.0 * units::g0 * 0.08, W = B - 6.0;
  double lo = -0.13, hi = 0.13;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (submergedFraction(mid, 0.26) < W / B ? lo : hi) = mid;
  }
  EXPECT_NEAR(lo, 0.1229, 1e-4);  // axis 12 cm down: 0.8 % of the section dry
  Scenario sc;
  sc.extra_masses = {{W / units::g0 - d.model.body.mass_kg, Eigen::Vector3d::Zero()}};
  sc.legs = {{60.0, 0.0, 0.0}};
  // Released at that draught it stays; released deeper it rises.
  sc.initial_depth_m = lo;
  const SimTrace at_rest = simulate(d.model, off, WaterColumn::uniform(1000.0), sc, opt);
  EXPECT_NEAR(at_rest.depth_m.back(), lo, 1e-6);
  sc.initial_depth_m = 1.0;
  const SimTrace rising = simulate(d.model, off, WaterColumn::uniform(1000.0), sc, opt);
  EXPECT_LT(*std::min_element(rising.depth_m.begin(), rising.depth_m.end()), 0.13);
  EXPECT_GT(*std::min_element(rising.depth_m.begin(), rising.depth_m.end()), -0.13);  // never leaves the water
  EXPECT_NEAR(submergedFraction(-0.13, 0.26), 0.0, 1e-12);
  EXPECT_NEAR(submergedFraction(0.0, 0.26), 0.5, 1e-12);
  EXPECT_NEAR(submergedFraction(0.13, 0.26), 1.0, 1e-12);
}

TEST(Simulator, RejectsEmptyOrBadScenario) {
  const Delphin2 d;
  const WaterColumn w = WaterColumn::uniform(1000.0);
  EXPECT_THROW((void)simulate(d.model, d.autopilot, w, Scenario{}), InputError);
  Scenario sc = hover(10.0);
  sc.legs[0].duration_s = -1.0;
  EXPECT_THROW((void)simulate(d.model, d.autopilot, w, sc), InputError);
}

}  // namespace
}  // namespace auv::sim
