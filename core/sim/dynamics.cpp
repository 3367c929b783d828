#include "sim/dynamics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/units.h"

namespace auv::sim {
namespace {

// core/hydrostatics restoringForces (Fossen eq. 4.6) with the CB at the
// origin, written on precomputed sines and cosines: the integrator needs the
// same four trig values for the kinematics, and sincos is the single largest
// cost of a step. tests/core/sim/dynamics_test.cpp checks this against
// restoringForces to 1e-12 for arbitrary attitudes, weights and CG offsets,
// so the simulator and the ballast analysis cannot drift apart.
// Returns [X, Z, K, M] of g(eta).
// W_minus_B = W - B, m = W r_g - B r_b = W r_g (r_b = 0).
inline Eigen::Vector4d restoringOnTrig(double W_minus_B, const Eigen::Vector3d& m, double sph, double cph,
                                       double sth, double cth) {
  return {W_minus_B * sth, -W_minus_B * cth * cph, -m.y() * cth * cph + m.z() * cth * sph,
          m.z() * sth + m.x() * cth * cph};
}

// sin and cos of base + d from those of base, for the small d between the
// stages of one RK4 step: angle addition with Taylor series of d to d^10,
// which for |d| < 0.1 rad is exact to rounding (next term < 3e-19). Saves
// three of the four sincos() calls per angle and step; larger d falls back.
inline void sinCosNear(double angle, const Trig1& base, double& s, double& c) {
  const double d = angle - base.angle;
  if (std::abs(d) >= 0.1) {
    s = std::sin(angle);
    c = std::cos(angle);
    return;
  }
  // Horner form of the Taylor series, 1/k! as literals (no divisions).
  const double d2 = d * d;
  const double sd =
      d * (1.0 + d2 * (-1.0 / 6.0 + d2 * (1.0 / 120.0 + d2 * (-1.0 / 5040.0 + d2 * (1.0 / 362880.0)))));
  const double cd = 1.0 + d2 * (-0.5 + d2 * (1.0 / 24.0 + d2 * (-1.0 / 720.0 + d2 * (1.0 / 40320.0 +
                                                                                    d2 * (-1.0 / 3628800.0)))));
  s = base.s * cd + base.c * sd;
  c = base.c * cd - base.s * sd;
}

}  // namespace

Dynamics::Dynamics(const VehicleModel& model)
    : model_(&model), vol23_(std::cbrt(model.body.hull.volume_m3 * model.body.hull.volume_m3)) {
  setMassProperties(model.body.mass_kg, model.body.r_g_m);
}

void Dynamics::setMassProperties(double mass_kg, const Eigen::Vector3d& r_g_m, double extra_Ixx_kgm2,
                                 double extra_Iyy_kgm2) {
  mass_ = mass_kg;
  r_g_ = r_g_m;
  Ixx_ = model_->body.Ixx_kgm2 + extra_Ixx_kgm2;
  Iyy_ = model_->body.Iyy_kgm2 + extra_Iyy_kgm2;
  const Hydrodynamics& h = model_->hydro;
  m_diag_ << mass_ - h.Xudot_kg, mass_ - h.Zwdot_kg, Iyy_ - h.Mqdot_kgm2, Ixx_ - h.Kpdot_kgm2;
  m_inv_ = m_diag_.cwiseInverse();
  updateConstants();
}

void Dynamics::setStepInputs(const StepInputs& in) {
  in_ = in;
  updateConstants();
}

void Dynamics::updateConstants() {
  const VehicleModel& m = *model_;
  const double rho = in_.water_density_kgm3;
  const double L = m.body.reference_length_m;
  const double L2 = L * L;
  const Hydrodynamics& h = m.hydro;
  StepConstants& k = k_;
  k.Zw = 0.5 * rho * L2 * h.Zw_prime;
  k.Zq = 0.5 * rho * L2 * L * h.Zq_prime;
  k.Mw = 0.5 * rho * L2 * L * h.Mw_prime;
  k.Mq = 0.5 * rho * L2 * L2 * h.Mq_prime;
  k.half_rho_vol23 = 0.5 * rho * vol23_;
  k.m_xg = mass_ * r_g_.x();
  k.m_zg = mass_ * r_g_.z();
  k.m_minus_Zwdot = mass_ - h.Zwdot_kg;
  k.m_minus_Xudot = mass_ - h.Xudot_kg;
  k.W_minus_B = in_.weight_n - in_.buoyancy_n;
  k.Wrg = in_.weight_n * r_g_;

  // Everything of eq. 11-21 that depends only on the held actuator state:
  // what remains per evaluation is the dependence on u, w, q. The tests
  // compare the result with the stand-alone equations in actuator_forces.h.
  const ActuatorState& a = in_.actuators;
  const Propeller& p = m.prop;
  const double n = a.prop_rps;
  if (n > 1e-9) {
    const double D = p.diameter_m;
    const double rho_n2_D4 = rho * n * n * D * D * D * D;
    k.prop_J_per_u = (1.0 - p.wake_fraction) / (n * D * p.c1);  // J / c1 per m/s
    k.prop_thrust0 = rho_n2_D4 * p.KT0 * (1.0 - p.thrust_deduction);
    k.prop_torque0 = p.torque_sign * rho_n2_D4 * D * p.KQ0;
  } else {
    k.prop_J_per_u = k.prop_thrust0 = k.prop_torque0 = 0.0;
  }
  const double delta_deg = units::radToDeg(a.plane_rad);
  k.plane_X = m.planes.X_uudd_per_deg2 * delta_deg * delta_deg;
  k.plane_Z = m.planes.Z_uud_per_deg * delta_deg;
  k.plane_M = m.planes.M_uud_per_deg * delta_deg;
  for (int i = 0; i < m.thruster_count; ++i) {
    const TunnelThruster& t = m.thrusters[i];
    const double nr = a.thruster_rpm[i];
    const double D2 = t.diameter_m * t.diameter_m;
    k.th_static[i] = rho * std::abs(nr) * nr * D2 * D2 * t.KT_per_rpm2;
    k.th_axial[i] = nr != 0.0 ? t.c_th2 * 60.0 / (nr * t.diameter_m) : 0.0;
    k.th_jet[i] = std::sqrt(rho * std::numbers::pi * D2 / 4.0);  // u / u_j = |u| k / sqrt(|F|)
  }
}

template <bool kBreakdown>
StateVector Dynamics::evaluate(const StateVector& s, const Trig1* theta0, const Trig1* phi0,
                               ForceBreakdown* out) const {
  const VehicleModel& m = *model_;
  const Hydrodynamics& h = m.hydro;
  const StepConstants& k = k_;
  const double u = s[kU], w = s[kW], q = s[kQ], p = s[kP];
  double sth, cth, sph, cph;
  if (theta0 != nullptr) {
    sinCosNear(s[kTheta], *theta0, sth, cth);
    sinCosNear(s[kPhi], *phi0, sph, cph);
  } else {
    sth = std::sin(s[kTheta]);
    cth = std::cos(s[kTheta]);
    sph = std::sin(s[kPhi]);
    cph = std::cos(s[kPhi]);
  }
  const double au = std::abs(u), uu = au * u;

  // tau: propeller (eq. 11-15), tunnel thrusters (eq. 16, 17), stern planes (eq. 18-21).
  double kt_ratio = 1.0;  // K_T / K_T0; J < 0 uses the bollard value
  if (u > 0.0 && k.prop_thrust0 != 0.0) {
    const double x = u * k.prop_J_per_u;
    kt_ratio = 1.0 - (m.prop.c2 == 1.0 ? x : std::pow(x, m.prop.c2));
  }
  const double F_prop = k.prop_thrust0 * kt_ratio;
  Force4 tau(F_prop + k.plane_X * uu, k.plane_Z * uu, k.plane_M * uu, k.prop_torque0 * kt_ratio);
  // d_tau (eq. 8-9): surge drag of the thruster jets.
  double d_tau_x = 0.0;
  std::array<double, kMaxThrusters> F_th{};
  if (m.thruster_count > 0) {
    const double fwd = std::exp(-m.thrusters[0].c_th1_s2_per_m2 * u * u);
    const ThrusterDragFit& f = m.thruster_drag;
    for (int i = 0; i < m.thruster_count; ++i) {
      if (k.th_static[i] == 0.0) continue;
      const TunnelThruster& t = m.thrusters[i];
      const double axial = std::clamp(1.0 - (w - q * t.x_m) * k.th_axial[i], 0.0, 2.0);
      F_th[i] = k.th_static[i] * fwd * axial;
      tau[1] += F_th[i];
      tau[2] -= t.x_m * F_th[i];  // a downward force forward of CB pitches nose down
      if (F_th[i] != 0.0) {
        const double r = au * k.th_jet[i] / std::sqrt(std::abs(F_th[i]));
        d_tau_x -= k.half_rho_vol23 * uu * (f.a1 * std::exp(-f.b1 * r) + f.a2 * std::exp(-f.b2 * r));
      }
    }
  }

  // -D(nu) nu (eq. 4); the speed-proportional derivatives use |u| on the
  // diagonal so that they stay dissipative when the vehicle backs up.
  Force4 damp((h.Xu_kg_per_s + h.Xuu_kg_per_m * au) * u,
              (k.Zw * au + h.Zww_kg_per_m * std::abs(w)) * w + (k.Zq * u + h.Zqq_kgm * std::abs(q)) * q,
              (k.Mw * u + h.Mww_kg * std::abs(w)) * w + (k.Mq * au + h.Mqq_kgm2 * std::abs(q)) * q,
              (h.Kp_kgm2_per_s + h.Kpp_kgm2 * std::abs(p)) * p);

  // -C(nu) nu (eq. 3): rigid-body and added-mass Coriolis/centripetal terms,
  // c13 = -m (x_g q - w) - Z_wdot w, c23 = -m (z_g q + u) + X_udot u.
  const double c13 = -k.m_xg * q + k.m_minus_Zwdot * w;
  const double c23 = -k.m_zg * q - k.m_minus_Xudot * u;
  // The added-mass part of c13 u + c23 w is the Munk moment (X_udot - Z_wdot) u w;
  // munk_factor 0 removes it (it is then inside M_w).
  const double munk_removed = (1.0 - h.munk_factor) * (h.Xudot_kg - h.Zwdot_kg) * u * w;
  const Force4 cor(-c13 * q, -c23 * q, c13 * u + c23 * w - munk_removed, 0.0);

  // -g(eta) (eq. 5), CB at the origin.
  const Eigen::Vector4d g = restoringOnTrig(k.W_minus_B, k.Wrg, sph, cph, sth, cth);
  const Force4 rest(-g[0], -g[1], -g[3], -g[2]);

  const Force4 total = tau + Force4(d_tau_x, 0, 0, 0) + damp + cor + rest + in_.external;

  StateVector ds;
  ds.head<4>() << total[0] * m_inv_[0], total[1] * m_inv_[1], total[2] * m_inv_[2], total[3] * m_inv_[3];
  // Kinematics (eq. 6-7) extended by roll (v = r = 0): reduces to eq. 7 at phi = 0.
  ds[kX] = u * cth + w * sth * cph;
  ds[kZ] = -u * sth + w * cth * cph;
  ds[kTheta] = q * cph;
  ds[kPhi] = p + q * sph * sth / cth;

  if constexpr (kBreakdown) {
    out->actuators = tau;
    out->tunnel_drag = Force4(d_tau_x, 0, 0, 0);
    out->damping = damp;
    out->coriolis = cor;
    out->restoring = rest;
    out->prop_thrust_n = F_prop;
    out->thruster_n = F_th;
  }
  return ds;
}

StateVector Dynamics::derivative(const StateVector& s) const {
  return evaluate<false>(s, nullptr, nullptr, nullptr);
}

ForceBreakdown Dynamics::breakdown(const StateVector& s) const {
  ForceBreakdown b;
  evaluate<true>(s, nullptr, nullptr, &b);
  return b;
}

void Dynamics::rk4Step(StateVector& s, double dt) const {
  const Trig1& th = last_theta_ = Trig1{s[kTheta], std::sin(s[kTheta]), std::cos(s[kTheta])};
  const Trig1& ph = last_phi_ = Trig1{s[kPhi], std::sin(s[kPhi]), std::cos(s[kPhi])};
  const StateVector k1 = evaluate<false>(s, &th, &ph, nullptr);
  const StateVector k2 = evaluate<false>(s + 0.5 * dt * k1, &th, &ph, nullptr);
  const StateVector k3 = evaluate<false>(s + 0.5 * dt * k2, &th, &ph, nullptr);
  const StateVector k4 = evaluate<false>(s + dt * k3, &th, &ph, nullptr);
  s += (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

}  // namespace auv::sim
