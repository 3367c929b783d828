// Hydrostatic and conservation self-tests of the equations of motion, each
// against an oracle that does not come from the simulator: core hydrostatics
// (restoring forces, static trim, restoring period), exact energy
// conservation, and a force balance solved by bisection.
#include "sim/dynamics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/units.h"
#include "hydrostatics/restoring.h"
#include "hydrostatics/static_trim.h"
#include "sim/actuator_forces.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

using testing::Delphin2;
constexpr double kRho = 1000.0;
constexpr double kDt = 0.05;

// Unforced vehicle (actuators at rest) with the given weight and buoyancy.
struct Free {
  explicit Free(VehicleModel m) : model(std::move(m)), dyn(model) {}
  void set(double W, double B, const Eigen::Vector3d& r_g) {
    dyn.setMassProperties(W / units::g0, r_g);
    StepInputs in;
    in.water_density_kgm3 = kRho;
    in.weight_n = W;
    in.buoyancy_n = B;
    dyn.setStepInputs(in);
  }
  void run(StateVector& s, double seconds, double dt = kDt) {
    const long n = std::lround(seconds / dt);
    for (long i = 0; i < n; ++i) dyn.rk4Step(s, dt);
  }
  VehicleModel model;
  Dynamics dyn;
};

VehicleModel withoutDamping(VehicleModel m) {
  m.hydro.Xuu_kg_per_m = m.hydro.Zww_kg_per_m = m.hydro.Zqq_kgm = m.hydro.Mww_kg = m.hydro.Mqq_kgm2 = 0.0;
  m.hydro.Zw_prime = m.hydro.Zq_prime = m.hydro.Mw_prime = m.hydro.Mq_prime = 0.0;
  m.hydro.Kp_kgm2_per_s = m.hydro.Kpp_kgm2 = 0.0;
  return m;
}

// Zero crossings of theta (or phi), linearly interpolated.
double measuredPeriod(Free& f, StateVector s, int index, double seconds) {
  std::vector<double> crossings;
  double prev = s[index], t = 0.0;
  const long n = std::lround(seconds / kDt);
  for (long i = 0; i < n; ++i) {
    f.dyn.rk4Step(s, kDt);
    t += kDt;
    if (prev > 0.0 && s[index] <= 0.0) crossings.push_back(t - kDt * s[index] / (s[index] - prev));
    prev = s[index];
  }
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(Dynamics, RestoringTermsAreCoreHydrostatics) {
  // The integrator evaluates g(eta) on shared sines/cosines; it must equal
  // core's restoringForces (Fossen eq. 4.6) for any attitude, W != B, any CG.
  const Delphin2 d;
  Dynamics dyn(d.model);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ang(-1.2, 1.2), off(-0.05, 0.08), wt(700.0, 800.0);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d rg(off(rng), off(rng), off(rng));
    const double W = wt(rng), B = wt(rng), phi = ang(rng), theta = ang(rng);
    dyn.setMassProperties(W / units::g0, rg);
    StepInputs in;
    in.weight_n = W;
    in.buoyancy_n = B;
    dyn.setStepInputs(in);
    StateVector s = StateVector::Zero();
    s[kTheta] = theta;
    s[kPhi] = phi;
    const Force4 r = dyn.breakdown(s).restoring;
    const Vector6d g = restoringForces(W, B, rg, Eigen::Vector3d::Zero(), phi, theta);
    EXPECT_NEAR(r[0], -g[0], 1e-10);
    EXPECT_NEAR(r[1], -g[2], 1e-10);
    EXPECT_NEAR(r[2], -g[4], 1e-10);
    EXPECT_NEAR(r[3], -g[3], 1e-10);
  }
}

TEST(Dynamics, ActuatorTermsAreTheEquationsOfActuatorForces) {
  // The integrator precomputes per step what the held actuator state fixes;
  // the result must be the stand-alone eq. 8-21 of actuator_forces.h.
  const Delphin2 d;
  const VehicleModel& m = d.model;
  Dynamics dyn(m);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> vel(-1.2, 1.2), rpm(-2500, 2500), dem(0, 30), fin(-0.5, 0.5);
  for (int i = 0; i < 300; ++i) {
    StepInputs in;
    in.water_density_kgm3 = 1000.0 + 25.0 * (i % 2);
    in.actuators.prop_rps = propellerRpsFromDemand(m.prop, dem(rng));
    in.actuators.thruster_rpm = {i % 7 ? rpm(rng) : 0.0, rpm(rng)};
    in.actuators.plane_rad = fin(rng);
    dyn.setStepInputs(in);
    StateVector s = StateVector::Zero();
    s[kU] = vel(rng);
    s[kW] = 0.3 * vel(rng);
    s[kQ] = 0.3 * vel(rng);
    const ForceBreakdown b = dyn.breakdown(s);
    const double rho = in.water_density_kgm3, u = s[kU];
    const PropellerLoads prop = propellerLoads(m.prop, rho, u, in.actuators.prop_rps);
    const PlaneForces fins = sternPlaneForces(m.planes, u, units::radToDeg(in.actuators.plane_rad));
    double Z = fins.Z_n, M = fins.M_nm, dX = 0.0;
    const double half_rho_vol23 = 0.5 * rho * std::pow(m.body.hull.volume_m3, 2.0 / 3.0);
    for (int k = 0; k < 2; ++k) {
      const TunnelThruster& t = m.thrusters[k];
      const double F = tunnelThrusterForceN(t, rho, std::exp(-t.c_th1_s2_per_m2 * u * u), s[kW] - s[kQ] * t.x_m,
                                            in.actuators.thruster_rpm[k]);
      Z += F;
      M -= t.x_m * F;
      dX += thrusterDragN(m.thruster_drag, rho, half_rho_vol23, u, F, t.diameter_m);
    }
    const double tol = 1e-9;
    EXPECT_NEAR(b.actuators[0], prop.thrust_n + fins.X_n, tol);
    EXPECT_NEAR(b.actuators[1], Z, tol);
    EXPECT_NEAR(b.actuators[2], M, tol);
    EXPECT_NEAR(b.actuators[3], m.prop.torque_sign * prop.torque_nm, tol);
    EXPECT_NEAR(b.tunnel_drag[0], dX, tol);
  }
}

TEST(Dynamics, Rk4StepEqualsTextbookRk4) {
  // rk4Step reuses the step's sines and cosines across its stages; it must
  // give the classical RK4 on derivative() to rounding.
  const Delphin2 d;
  Dynamics dyn(d.model);
  StepInputs in;
  in.weight_n = 780.0;
  in.buoyancy_n = 786.0;
  in.actuators.prop_rps = 4.0;
  in.actuators.thruster_rpm = {900.0, 1100.0};
  in.actuators.plane_rad = 0.1;
  dyn.setStepInputs(in);
  StateVector s = StateVector::Zero();
  s << 0.8, 0.1, 0.3, 1.5, 0.0, 2.0, -0.4, 0.2;
  for (int i = 0; i < 50; ++i) {
    const double dt = 0.05;
    const StateVector k1 = dyn.derivative(s);
    const StateVector k2 = dyn.derivative(s + 0.5 * dt * k1);
    const StateVector k3 = dyn.derivative(s + 0.5 * dt * k2);
    const StateVector k4 = dyn.derivative(s + dt * k3);
    const StateVector ref = s + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    dyn.rk4Step(s, dt);
    EXPECT_LT((s - ref).cwiseAbs().maxCoeff(), 1e-13) << "step " << i;
    s = ref;
  }
}

TEST(Dynamics, CoriolisDoesNoWork) {
  // C(nu) of eq. 3 is skew-symmetric: nu^T C(nu) nu = 0 for every nu.
  const Delphin2 d;
  Dynamics dyn(d.model);
  dyn.setStepInputs({});
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> v(-2.0, 2.0);
  for (int i = 0; i < 100; ++i) {
    StateVector s = StateVector::Zero();
    s[kU] = v(rng);
    s[kW] = v(rng);
    s[kQ] = v(rng);
    s[kP] = v(rng);
    const Force4 c = dyn.breakdown(s).coriolis;
    EXPECT_NEAR(c[0] * s[kU] + c[1] * s[kW] + c[2] * s[kQ] + c[3] * s[kP], 0.0, 1e-10);
  }
}

TEST(Dynamics, NeutralVehicleAtRestStaysPut) {
  const Delphin2 d;
  Free f(d.model);
  const double W = d.model.body.mass_kg * units::g0;
  f.set(W, W, d.model.body.r_g_m);
  StateVector s = StateVector::Zero();
  s[kZ] = 5.0;
  f.run(s, 600.0);
  EXPECT_NEAR(s[kZ], 5.0, 1e-12);
  EXPECT_NEAR(s[kX], 0.0, 1e-12);
  EXPECT_NEAR(s[kTheta], 0.0, 1e-12);
  EXPECT_NEAR(s[kPhi], 0.0, 1e-12);
  EXPECT_NEAR(s.head<4>().norm(), 0.0, 1e-12);
}

TEST(Dynamics, HeavyVehicleStartsToSinkWithAddedMassInTheInertia) {
  // At rest, w_dot = (W - B) / (m - Z_wdot): added mass slows the start.
  Delphin2 d;
  d.model.hydro.Mww_kg = 0.0;  // keep the fall pure heave (M_|w|w would pitch it into a glide)
  Free f(d.model);
  const double m = d.model.body.mass_kg, W = m * units::g0;
  f.set(W, W - 6.0, d.model.body.r_g_m);
  const StateVector ds = f.dyn.derivative(StateVector::Zero());
  EXPECT_NEAR(ds[kW], 6.0 / (m + 65.5), 1e-12);
  // Terminal sink rate from Z_|w|w (Appendix B's free-ascent relation, B.1).
  StateVector s = StateVector::Zero();
  f.run(s, 120.0);
  EXPECT_NEAR(s[kW], std::sqrt(6.0 / 183.0), 1e-6);
}

TEST(Dynamics, CgOffsetGivesTheStaticTrimOfCoreHydrostatics) {
  const Delphin2 d;
  Free f(d.model);
  const double W = d.model.body.mass_kg * units::g0;
  // CG 10 mm forward and 5 mm to starboard of the CB, 60 mm below it.
  const Eigen::Vector3d rg(0.010, 0.005, 0.06);
  f.set(W, W, rg);
  const StaticTrim trim = staticTrim(W, W, rg, Eigen::Vector3d::Zero());
  // Exactly at the static trim the vehicle stays there ...
  StateVector s = StateVector::Zero();
  s[kTheta] = trim.pitch_rad;
  s[kPhi] = trim.roll_rad;
  f.run(s, 300.0);
  EXPECT_NEAR(s[kTheta], trim.pitch_rad, 1e-10);
  EXPECT_NEAR(s[kPhi], trim.roll_rad, 1e-10);
  // ... and released level it swings there and settles.
  StateVector s0 = StateVector::Zero();
  f.run(s0, 2000.0);
  EXPECT_NEAR(units::radToDeg(s0[kTheta]), units::radToDeg(trim.pitch_rad), 0.05);
  EXPECT_NEAR(units::radToDeg(s0[kPhi]), units::radToDeg(trim.roll_rad), 0.01);
  EXPECT_NEAR(units::radToDeg(trim.pitch_rad), -9.4302, 1e-4);  // atan2(-10, hypot(5, 60))
}

TEST(Dynamics, PitchAndRollPeriodsMatchRestoringPeriod) {
  // T = 2 pi sqrt((I + I_added) / (W BG)) (core hydrostatics).
  const Delphin2 d;
  Free f(withoutDamping(d.model));
  const double W = d.model.body.mass_kg * units::g0, bg = 0.06;
  f.set(W, W, {0, 0, bg});
  StateVector s = StateVector::Zero();
  s[kTheta] = 0.01;
  const double Tpitch = restoringPeriod(35.0 + 14.17, W, bg);
  EXPECT_NEAR(Tpitch, 6.4465, 1e-3);
  EXPECT_NEAR(measuredPeriod(f, s, kTheta, 12 * Tpitch), Tpitch, 1e-3 * Tpitch);
  StateVector r = StateVector::Zero();
  r[kPhi] = 0.01;
  const double Troll = restoringPeriod(d.model.body.Ixx_kgm2 - d.model.hydro.Kpdot_kgm2, W, bg);
  EXPECT_NEAR(measuredPeriod(f, r, kPhi, 12 * Troll), Troll, 1e-3 * Troll);
}

TEST(Dynamics, UndampedMotionConservesEnergy) {
  // Without damping or thrust, kinetic energy 1/2 nu^T M nu plus the
  // potential energy of weight and buoyancy is constant: checks C(nu), g(eta)
  // and the kinematics together, for large angles and W = B with a CG offset.
  // At 200 Hz RK4 is conservative to 1e-6; at the model's 20 Hz it damps the
  // fast (0.8 s) roll mode numerically by about 3e-5 of its energy per step,
  // which is why the assertion below uses the small step.
  const Delphin2 d;
  Free f(withoutDamping(d.model));
  const double W = d.model.body.mass_kg * units::g0;
  const Eigen::Vector3d rg(0.02, 0.01, 0.06);
  f.set(W, W, rg);
  const Eigen::Vector4d M = f.dyn.massDiagonal();
  auto energy = [&](const StateVector& s) {
    const double kin = 0.5 * (M[0] * s[kU] * s[kU] + M[1] * s[kW] * s[kW] + M[2] * s[kQ] * s[kQ] +
                              M[3] * s[kP] * s[kP]);
    const double sth = std::sin(s[kTheta]), cth = std::cos(s[kTheta]);
    const double sph = std::sin(s[kPhi]), cph = std::cos(s[kPhi]);
    // Depth of the CG below the CB in earth axes; potential -W z_cg + B z_cb.
    const double dz = -sth * rg.x() + cth * sph * rg.y() + cth * cph * rg.z();
    return kin - W * dz;
  };
  StateVector s = StateVector::Zero();
  s[kU] = 0.3;
  s[kW] = -0.1;
  s[kQ] = 0.2;
  s[kP] = 0.5;
  s[kTheta] = 0.4;
  s[kPhi] = -0.3;
  const double e0 = energy(s);
  f.run(s, 100.0, 0.005);
  EXPECT_NEAR(energy(s), e0, 1e-6 * std::abs(e0));
}

TEST(Dynamics, SteadySurgeSpeedBalancesThrustAndDrag) {
  // Neutral vehicle, propeller at demand 22, planes and thrusters still: the
  // final speed is the root of F_prop(u) + X_|u|u |u| u = 0 (bisection).
  const Delphin2 d;
  Free f(d.model);
  const double W = d.model.body.mass_kg * units::g0;
  f.dyn.setMassProperties(d.model.body.mass_kg, d.model.body.r_g_m);
  StepInputs in;
  in.water_density_kgm3 = kRho;
  in.weight_n = W;
  in.buoyancy_n = W;
  in.actuators.prop_rps = propellerRpsFromDemand(d.model.prop, 22.0);
  f.dyn.setStepInputs(in);
  StateVector s = StateVector::Zero();
  f.run(s, 300.0);
  double lo = 0.1, hi = 3.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double net = propellerThrustN(d.model.prop, kRho, mid, in.actuators.prop_rps) - 6.5 * mid * mid;
    (net > 0 ? lo : hi) = mid;
  }
  EXPECT_NEAR(s[kU], lo, 1e-6);
  EXPECT_GT(s[kU], 1.0);  // neutral, no thruster drag: a little above the paper's 1.0 m/s
  EXPECT_LT(s[kU], 1.1);
  // The propeller torque rolls the vehicle to Q / (W BG).
  const double Q = propellerLoads(d.model.prop, kRho, s[kU], in.actuators.prop_rps).torque_nm;
  EXPECT_NEAR(s[kPhi], std::asin(Q / (W * 0.06)), 1e-6);
}

}  // namespace
}  // namespace auv::sim
