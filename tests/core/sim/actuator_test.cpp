// Each actuator equation of the Delphin2 paper against a value worked out by
// hand from the printed equation and Appendix A, plus the response of the
// actuators to their demands.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/units.h"
#include "sim/actuator_forces.h"
#include "sim/actuator_state.h"
#include "sim/power_model.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

using testing::Delphin2;
constexpr double kRho = 1000.0;

TEST(Propeller, SpeedFromDemandIsEquation13) {
  const Delphin2 d;
  // n = -0.0055 d^2 + 0.4136 d - 1.7895
  EXPECT_NEAR(propellerRpsFromDemand(d.model.prop, 22.0), -0.0055 * 484 + 0.4136 * 22 - 1.7895, 1e-12);
  EXPECT_NEAR(propellerRpsFromDemand(d.model.prop, 22.0), 4.6477, 1e-4);
  EXPECT_NEAR(propellerRpsFromDemand(d.model.prop, 10.0), 1.7965, 1e-4);
  // Below d ~ 4.6 the quadratic is negative: the motor does not turn.
  EXPECT_EQ(propellerRpsFromDemand(d.model.prop, 0.0), 0.0);
  EXPECT_EQ(propellerRpsFromDemand(d.model.prop, 4.0), 0.0);
}

TEST(Propeller, ThrustIsEquations11To14) {
  const Delphin2 d;
  const Propeller& p = d.model.prop;
  // Bollard (u = 0): K_T = K_T0.
  const double n = 4.6477;
  EXPECT_NEAR(propellerThrustN(p, kRho, 0.0, n), kRho * n * n * std::pow(0.305, 4) * 0.0946 * (1 - 0.11), 1e-9);
  // u = 1 m/s: J = 1 * (1 - 0.36) / (4.6477 * 0.305) = 0.45148
  const double J = 0.64 / (n * 0.305);
  EXPECT_NEAR(J, 0.45148, 1e-5);
  const double KT = 0.0946 * (1 - std::pow(J / 0.6999, 1.5205));
  EXPECT_NEAR(propellerKT(p, J), KT, 1e-15);
  EXPECT_NEAR(propellerThrustN(p, kRho, 1.0, n), kRho * n * n * std::pow(0.305, 4) * KT * 0.89, 1e-9);
  // K_T vanishes at J = c_prop,1 (figure 4 crosses zero there).
  EXPECT_NEAR(propellerKT(p, 0.6999), 0.0, 1e-15);
  EXPECT_EQ(propellerThrustN(p, kRho, 1.0, 0.0), 0.0);
}

TEST(TunnelThruster, StaticThrustAndItsInverseEquation25) {
  const Delphin2 d;
  const TunnelThruster& t = d.model.thrusters[0];
  // F = rho |n| n D^4 K_T,th, n in rpm: 1000 rpm -> 3.0901 N
  EXPECT_NEAR(tunnelThrusterForceN(t, kRho, 1.0, 0.0, 1000.0), kRho * 1e6 * std::pow(0.07, 4) * 1.2870e-4, 1e-12);
  EXPECT_NEAR(tunnelThrusterForceN(t, kRho, 1.0, 0.0, 1000.0), 3.0901, 1e-4);
  EXPECT_NEAR(tunnelThrusterForceN(t, kRho, 1.0, 0.0, -1000.0), -3.0901, 1e-4);
  for (double F : {-5.0, -0.3, 0.0, 0.7, 3.0, 12.0}) {
    EXPECT_NEAR(tunnelThrusterForceN(t, kRho, 1.0, 0.0, thrusterRpmForForce(t, kRho, F)), F, 1e-12);
  }
}

TEST(TunnelThruster, DeductionFactorsOfEquation16) {
  const Delphin2 d;
  const TunnelThruster& t = d.model.thrusters[0];
  const double F0 = tunnelThrusterForceN(t, kRho, 1.0, 0.0, 1200.0);
  // Forward speed: exp(-c_th1 u^2), at u = 1 m/s a factor 0.7047.
  const double fwd = std::exp(-0.35 * 1.0);
  EXPECT_NEAR(tunnelThrusterForceN(t, kRho, fwd, 0.0, 1200.0) / F0, 0.70469, 1e-5);
  // Axial inflow 0.1 m/s at 1200 rpm = 20 rev/s: 1 - 1.5 * 0.1 / (20 * 0.07).
  EXPECT_NEAR(tunnelThrusterForceN(t, kRho, 1.0, 0.1, 1200.0) / F0, 1 - 1.5 * 0.1 / 1.4, 1e-12);
}

TEST(TunnelThruster, JetDragIsEquations8And9) {
  const Delphin2 d;
  const ThrusterDragFit& f = d.model.thruster_drag;
  // At u / u_j -> 0 the fit gives 0.5660 + 0.0565 (figure 3 intercept).
  EXPECT_NEAR(f.a1 + f.a2, 0.6225, 1e-12);
  const double F = 3.0, u = 0.5, D = 0.07;
  const double uj = std::sqrt(4 * F / (kRho * std::numbers::pi * D * D));
  EXPECT_NEAR(uj, 0.88291, 1e-5);
  const double r = u / uj;
  const double dCd = 0.5660 * std::exp(-7.6089 * r) + 0.0565 * std::exp(-0.8968 * r);
  const double half_rho_vol23 = 0.5 * kRho * std::pow(0.08, 2.0 / 3.0);
  const double expected = -0.5 * kRho * std::pow(0.08, 2.0 / 3.0) * u * u * dCd;
  EXPECT_NEAR(thrusterDragN(f, kRho, half_rho_vol23, u, F, D), expected, 1e-12);
  EXPECT_NEAR(expected, -0.96572, 1e-5);
  // A stopped thruster adds no drag; drag opposes motion when backing up.
  EXPECT_EQ(thrusterDragN(f, kRho, half_rho_vol23, u, 0.0, D), 0.0);
  EXPECT_NEAR(thrusterDragN(f, kRho, half_rho_vol23, -u, F, D), -expected, 1e-12);
}

TEST(SternPlanes, Equations18To20) {
  const Delphin2 d;
  const PlaneForces f = sternPlaneForces(d.model.planes, 1.0, 10.0);
  EXPECT_NEAR(f.X_n, -0.0036 * 100, 1e-12);
  EXPECT_NEAR(f.Z_n, 3.241, 1e-12);
  EXPECT_NEAR(f.M_nm, 3.254, 1e-12);
  // |u|u: reversing makes the lift change sign (the paper's stability fix).
  EXPECT_NEAR(sternPlaneForces(d.model.planes, -1.0, 10.0).Z_n, -3.241, 1e-12);
  // The moment/force ratio places the planes about 1 m aft of the CB.
  EXPECT_NEAR(f.M_nm / f.Z_n, 1.004, 1e-3);
}

TEST(ActuatorDynamics, PropellerFollowsAFirstOrderLag) {
  Delphin2 d;
  d.model.prop.max_rate_rps_per_s = 1e9;  // isolate the lag
  const double dt = 0.05;
  const ActuatorDynamics dyn(d.model, dt);
  ActuatorState s;
  ActuatorDemand demand;
  demand.prop_demand = 22.0;
  const double target = propellerRpsFromDemand(d.model.prop, 22.0);
  const int steps = static_cast<int>(std::lround(d.model.prop.time_constant_s / dt));
  for (int i = 0; i < steps; ++i) dyn.advance(s, demand);
  EXPECT_NEAR(s.prop_rps / target, 1 - std::exp(-1.0), 1e-12);
}

TEST(ActuatorDynamics, RateLimitsDeadbandAndSaturation) {
  const Delphin2 d;
  const double dt = 0.05;
  const ActuatorDynamics dyn(d.model, dt);
  ActuatorState s;
  ActuatorDemand demand;
  // Stern plane slews at 40 deg/s: 0.25 s after a 20 deg step it is at 10 deg.
  demand.plane_rad = units::degToRad(20.0);
  for (int i = 0; i < 5; ++i) dyn.advance(s, demand);
  EXPECT_NEAR(units::radToDeg(s.plane_rad), 10.0, 1e-9);
  // Saturates at 30 deg.
  demand.plane_rad = units::degToRad(90.0);
  for (int i = 0; i < 100; ++i) dyn.advance(s, demand);
  EXPECT_NEAR(units::radToDeg(s.plane_rad), 30.0, 1e-9);
  // Tunnel thrusters: inside the 150 rpm deadband the motor stays still.
  demand.thruster_rpm = {120.0, -140.0};
  for (int i = 0; i < 100; ++i) dyn.advance(s, demand);
  EXPECT_EQ(s.thruster_rpm[0], 0.0);
  EXPECT_EQ(s.thruster_rpm[1], 0.0);
  demand.thruster_rpm = {1e5, -1e5};
  for (int i = 0; i < 200; ++i) dyn.advance(s, demand);
  EXPECT_NEAR(s.thruster_rpm[0], 2500.0, 1e-6);
  EXPECT_NEAR(s.thruster_rpm[1], -2500.0, 1e-6);
}

TEST(Power, HoverHoldPowerScalesWithBuoyancyToTheThreeHalves) {
  // Thrust ~ n^2 and motor power ~ n^3, so holding force F costs ~ F^1.5.
  const Delphin2 d;
  const double p6 = hoverHoldPowerW(d.model, 6.0, kRho) - hoverHoldPowerW(d.model, 0.0, kRho);
  const double p1 = hoverHoldPowerW(d.model, 1.0, kRho) - hoverHoldPowerW(d.model, 0.0, kRho);
  EXPECT_NEAR(p6 / p1, std::pow(6.0, 1.5), 1e-9);
  // Calibration: Table 1 hover row, th-frt + th-aft = 10.73 + 11.11 W at +6 N.
  EXPECT_NEAR(p6, 21.84, 0.5);
}

}  // namespace
}  // namespace auv::sim
