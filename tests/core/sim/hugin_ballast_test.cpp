// HUGIN 1000 flown with a known ballast state: installed kit pieces and a
// deliberate error set mass and CG exactly as core hydrostatics computes
// them, buoyancy is core hydrostatics' displaced mass, the settled flight is
// the solution of the steady force/moment balance, and heading hold turns at
// the rate the yaw balance allows.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "common/units.h"
#include "hydrostatics/balance.h"
#include "hydrostatics/mass_properties.h"
#include "seawater/depth_pressure.h"
#include "seawater/eos80.h"
#include "sim/simulator.h"
#include "sim/step_engine.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

using testing::HuginSim;

Scenario levelLeg(const HuginSim& h, double rpm, double seconds, BallastError err = {}) {
  Scenario sc;
  sc.extra_masses = installedWeights(h.profile, testing::huginInstalledKg());
  sc.ballast_error = err;
  sc.initial_depth_m = 50.0;
  sc.initial_speed_mps = 2.0;
  sc.legs = {{seconds, 50.0, rpm}};
  return sc;
}

template <class F>
double meanAfter(const SimTrace& tr, double t0, F&& f) {
  double s = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    if (tr.time_s[i] < t0) continue;
    s += f(i);
    ++n;
  }
  return s / n;
}

TEST(HuginBallast, InstalledWeightsAndErrorGiveCoreMassProperties) {
  const HuginSim h;
  const auto kg = testing::huginInstalledKg();
  // Oracle: core hydrostatics' particle sum in the profile frame.
  std::vector<MassItem> items = {{h.profile.mass_kg, h.profile.cb_m + Eigen::Vector3d(0, 0, h.profile.bg_m)}};
  for (std::size_t i = 0; i < kg.size(); ++i) items.push_back({kg[i], h.profile.points[i].position_m});
  const MassProperties mp = massProperties(items);

  const SimTrace ok = simulate(h.model(), h.autopilot(), testing::huginSea(), levelLeg(h, 160, 1.0));
  EXPECT_NEAR(ok.truth.mass_kg, 1563.8, 1e-9);
  EXPECT_NEAR(ok.truth.mass_kg, mp.mass_kg, 1e-9);
  EXPECT_NEAR(ok.truth.cg_x_m, mp.cg_m.x() - h.profile.cb_m.x(), 1e-12);
  EXPECT_NEAR(ok.truth.cg_y_m, mp.cg_m.y() - h.profile.cb_m.y(), 1e-12);
  EXPECT_NEAR(ok.truth.cg_z_m, mp.cg_m.z() - h.profile.cb_m.z(), 1e-12);
  EXPECT_LT(std::abs(ok.truth.cg_x_m), 1e-4);  // the example's kit trims it level to 0.1 mm

  const SimTrace bad = simulate(h.model(), h.autopilot(), testing::huginSea(),
                                levelLeg(h, 160, 1.0, {3.0, Eigen::Vector3d(0.005, 0.0, 0.0)}));
  EXPECT_NEAR(bad.truth.net_buoyancy_start_n - ok.truth.net_buoyancy_start_n, 3.0 * units::g0, 1e-9);
  EXPECT_NEAR(bad.truth.cg_x_m - ok.truth.cg_x_m, 0.005, 1e-15);
  EXPECT_NEAR(bad.truth.mass_kg, mp.mass_kg - 3.0, 1e-9);
  EXPECT_THROW((void)installedWeights(h.profile, std::vector<double>{1, 2, 3}), InputError);
  EXPECT_THROW((void)installedWeights(h.profile, std::vector<double>{41, 0, 0, 0}), InputError);  // over capacity
}

TEST(HuginBallast, BuoyancyIsCoreHydrostaticsDisplacedMass) {
  HuginSim h;
  VehicleModel m = h.model();
  // A hull that shrinks with pressure and grows with temperature, so every
  // term of V(T, p) matters.
  m.body.hull.compressibility_per_dbar = 3e-6;
  m.body.hull.thermal_expansion_per_degC = 6e-5;
  const WaterColumn sea = testing::huginSea();
  for (double z : {0.0, 12.0, 12.5, 50.0, 99.5, 100.0, 237.25}) {
    // Oracle: the cast's T/S interpolated by hand, UNESCO pressure at 60 N,
    // EOS-80 density, core's displaced mass.
    const double f = z <= 20 ? z / 20 : (z <= 100 ? (z - 20) / 80 : (z - 100) / 200);
    const double T = z <= 20 ? 9 - f : (z <= 100 ? 8 - f : 7 - 0.5 * f);
    const double S = z <= 20 ? 33.5 + f : (z <= 100 ? 34.5 + 0.5 * f : 35 + 0.1 * f);
    const double p = seawater::pressureFromDepth(z, 60.0);
    const WaterState ws{seawater::density(S, T, p), T, p};
    const double core_n = displacedMassKg(m.body.hull, ws) * units::g0;
    // Between the 1 m table rows the density is interpolated: 1e-7 relative.
    EXPECT_NEAR(buoyancyN(m, sea.at(z), z, false), core_n, 1e-7 * core_n) << z;
  }
}

// Steady level flight (q = p = 0, z_dot = 0) of the model's equations,
// solved by Newton for speed, pitch, plane angle (paper sign, deg) and roll.
Eigen::Vector4d steadyBalance(const VehicleModel& m, double rho, double W, double B, const Eigen::Vector3d& rg,
                              double n_rps, Eigen::Vector4d x) {
  const Hydrodynamics& h = m.hydro;
  const double L = m.body.reference_length_m, D = m.prop.diameter_m;
  auto residual = [&](const Eigen::Vector4d& v) {
    const double u = v[0], th = v[1], d = v[2], ph = v[3];
    const double w = u * std::tan(th) / std::cos(ph);  // z_dot = -u sin th + w cos th cos ph = 0
    const double J = u * (1 - m.prop.wake_fraction) / (n_rps * D);
    const double kt = 1 - J / m.prop.c1;  // c2 = 1 for HUGIN
    const double T = rho * n_rps * n_rps * std::pow(D, 4) * m.prop.KT0 * kt * (1 - m.prop.thrust_deduction);
    const double Q = m.prop.torque_sign * rho * n_rps * n_rps * std::pow(D, 5) * m.prop.KQ0 * kt;
    const double Zw = 0.5 * rho * L * L * h.Zw_prime * u, Mw = 0.5 * rho * std::pow(L, 3) * h.Mw_prime * u;
    const double ct = std::cos(th), st = std::sin(th), cp = std::cos(ph), sp = std::sin(ph);
    Eigen::Vector4d r;
    r[0] = T + h.Xuu_kg_per_m * u * u + m.planes.X_uudd_per_deg2 * u * u * d * d - (W - B) * st;
    r[1] = m.planes.Z_uud_per_deg * u * u * d + (Zw + h.Zww_kg_per_m * std::abs(w)) * w + (W - B) * ct * cp;
    r[2] = m.planes.M_uud_per_deg * u * u * d + (Mw + h.Mww_kg * std::abs(w)) * w + (h.Xudot_kg - h.Zwdot_kg) * u * w -
           W * (rg.z() * st + rg.x() * ct * cp);
    r[3] = Q - W * (-rg.y() * ct * cp + rg.z() * ct * sp);
    return r;
  };
  for (int it = 0; it < 50; ++it) {
    const Eigen::Vector4d r = residual(x);
    Eigen::Matrix4d Jm;
    for (int j = 0; j < 4; ++j) {
      Eigen::Vector4d xp = x;
      xp[j] += 1e-7;
      Jm.col(j) = (residual(xp) - r) / 1e-7;
    }
    x -= Jm.partialPivLu().solve(r);
  }
  return x;
}

TEST(HuginBallast, SettledFlightIsTheForceAndMomentBalance) {
  const HuginSim h;
  const WaterColumn sea = testing::huginSea();
  const BallastError err{3.0, Eigen::Vector3d(0.005, 0.0, 0.0)};  // 3 kg light, CG 5 mm forward
  for (double rpm : {120.0, 160.0}) {
    const SimTrace tr = simulate(h.model(), h.autopilot(), sea, levelLeg(h, rpm, 900.0, err));
    const double t0 = 600.0;
    const double u = meanAfter(tr, t0, [&](std::size_t i) { return tr.speed_mps[i]; });
    const double th = meanAfter(tr, t0, [&](std::size_t i) { return tr.pitch_rad[i]; });
    const double el = meanAfter(tr, t0, [&](std::size_t i) { return tr.elevator_rad[i]; });
    const double ph = meanAfter(tr, t0, [&](std::size_t i) { return tr.roll_rad[i]; });
    const double z = meanAfter(tr, t0, [&](std::size_t i) { return tr.depth_m[i]; });
    EXPECT_NEAR(z, 50.0, 0.01);
    const WaterSample ws = sea.at(50.0);
    const double W = tr.truth.mass_kg * units::g0;
    const double B = buoyancyN(h.model(), ws, 50.0, false);
    const Eigen::Vector3d rg(tr.truth.cg_x_m, tr.truth.cg_y_m, tr.truth.cg_z_m);
    const Eigen::Vector4d x = steadyBalance(h.model(), ws.density_kgm3, W, B, rg, rpm / 60.0, {u, th, 0.0, ph});
    EXPECT_NEAR(u, x[0], 1e-4) << rpm;
    EXPECT_NEAR(units::radToDeg(th), units::radToDeg(x[1]), 0.005) << rpm;
    EXPECT_NEAR(units::radToDeg(el), -x[2], 0.01) << rpm;  // log sign = -paper sign
    EXPECT_NEAR(units::radToDeg(ph), units::radToDeg(x[3]), 0.005) << rpm;
    // The error shows: 29 N of buoyancy held by hull lift at a nose-down
    // pitch and a 5 mm forward CG trimmed by the planes.
    EXPECT_LT(units::radToDeg(th), -0.2) << rpm;
    std::printf("rpm %.0f: u %.4f m/s, pitch %.3f deg, elevator %.3f deg, roll %.3f deg\n", rpm, u,
                units::radToDeg(th), units::radToDeg(el), units::radToDeg(ph));
  }
}

TEST(HuginHeading, YawByPitchSymmetryTurnsAtTheSteadyRate) {
  const HuginSim h;
  const VehicleModel& m = h.model();
  EXPECT_DOUBLE_EQ(m.yaw.Izz_kgm2, m.body.Iyy_kgm2);
  EXPECT_DOUBLE_EQ(m.yaw.Nrdot_kgm2, m.hydro.Mqdot_kgm2);
  EXPECT_DOUBLE_EQ(m.yaw.N_uud_per_deg, m.planes.M_uud_per_deg);
  ASSERT_TRUE(h.autopilot().heading.enabled);
  Scenario sc = levelLeg(h, 160, 20.0);
  sc.initial_heading_rad = units::degToRad(10.0);
  sc.legs.push_back({100.0, 50.0, 160.0, 0.0, units::degToRad(130.0)});
  SimOptions o;
  o.trace_interval_s = 0.2;
  const SimTrace tr = simulate(m, h.autopilot(), testing::huginSea(), sc, o);
  double max_rate = 0.0, max_heading = 0.0;
  for (std::size_t i = 1; i < tr.size(); ++i) {
    max_rate = std::max(max_rate, (tr.heading_rad[i] - tr.heading_rad[i - 1]) / 0.2);
    max_heading = std::max(max_heading, tr.heading_rad[i]);
  }
  // Oracle: with the rudder at the autopilot's 15 deg limit, the yaw balance
  // N_r |u| r + N_|r|r r^2 + N_d u^2 delta = 0 at the speed flown.
  const double u = tr.speed_mps[150];  // 30 s: mid-turn
  const double rho = testing::huginSea().at(50).density_kgm3;
  const double L = m.body.reference_length_m;
  const double a = -m.yaw.Nrr_kgm2, b = -0.5 * rho * std::pow(L, 4) * m.yaw.Nr_prime * u;
  const double c = m.yaw.N_uud_per_deg * u * u * 15.0;
  const double r_ss = (-b + std::sqrt(b * b + 4 * a * c)) / (2 * a);
  EXPECT_NEAR(max_rate, r_ss, 0.03 * r_ss);
  EXPECT_NEAR(units::radToDeg(tr.heading_rad[99]), 10.0, 0.05);  // held before the turn
  EXPECT_NEAR(units::radToDeg(tr.heading_rad.back()), 130.0, 0.2);
  EXPECT_LT(units::radToDeg(max_heading), 135.0);  // overshoot < 5 deg
  EXPECT_NEAR(tr.depth_m.back(), 50.0, 0.05);      // decoupled from the depth loop
  std::printf("turn: max rate %.3f deg/s, steady-state oracle %.3f deg/s at u %.3f\n",
              units::radToDeg(max_rate), units::radToDeg(r_ss), u);
}

}  // namespace
}  // namespace auv::sim
