#pragma once
// Force models of the Delphin2 actuators (paper sec. 3.2-3.3). Inline because
// the integrator calls them four times per step; each is one equation of the
// paper and is tested against hand-computed values.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/vehicle_model.h"

namespace auv::sim {

// Eq. 13: propeller speed [rev/s] from the motor-board demand. The quadratic
// is negative below a demand of ~4.6 (the motor does not turn): clip at 0.
inline double propellerRpsFromDemand(const Propeller& p, double demand) {
  const double d = std::clamp(demand, 0.0, p.max_demand);
  return std::max(0.0, (p.rps_a2 * d + p.rps_a1) * d + p.rps_a0);
}

// Eq. 12 with J from eq. 11. J < 0 (going astern) uses the bollard value; the
// fit is only defined for forward flow.
inline double propellerKT(const Propeller& p, double J) {
  if (J <= 0.0) return p.KT0;
  const double x = J / p.c1;
  return p.KT0 * (1.0 - (p.c2 == 1.0 ? x : std::pow(x, p.c2)));
}

struct PropellerLoads {
  double thrust_n = 0.0;
  double torque_nm = 0.0;  // shaft torque; the paper has no K_Q, we take K_Q/K_T constant (assumption)
};

// Eq. 11-14: thrust [N] at surge speed u [m/s] and shaft speed n [rev/s],
// and the shaft torque from the same K_T (one pow() per call).
inline PropellerLoads propellerLoads(const Propeller& p, double rho, double u, double n_rps) {
  if (n_rps <= 1e-9) return {};
  const double J = u * (1.0 - p.wake_fraction) / (n_rps * p.diameter_m);
  const double D = p.diameter_m;
  const double rho_n2_D4 = rho * n_rps * n_rps * D * D * D * D;
  const double KT = propellerKT(p, J);
  return {rho_n2_D4 * KT * (1.0 - p.thrust_deduction), p.KT0 > 0.0 ? rho_n2_D4 * D * p.KQ0 * KT / p.KT0 : 0.0};
}

inline double propellerThrustN(const Propeller& p, double rho, double u, double n_rps) {
  return propellerLoads(p, rho, u, n_rps).thrust_n;
}

// Eq. 16 for a vertical tunnel thruster. The forward-speed deduction uses the
// surge speed u; the second factor uses the flow along the tunnel axis
// (w - q x for a vertical tunnel at x) over n D with n in rev/s, i.e. a true
// advance ratio (docs/decisions/sim-tunnel-thruster.md). `forward_deduction`
// is exp(-c_th1 u^2), passed in so two thrusters share one exp().
inline double tunnelThrusterForceN(const TunnelThruster& t, double rho, double forward_deduction,
                                   double axial_speed_mps, double n_rpm) {
  if (n_rpm == 0.0) return 0.0;
  const double D2 = t.diameter_m * t.diameter_m;
  const double static_thrust = rho * std::abs(n_rpm) * n_rpm * D2 * D2 * t.KT_per_rpm2;
  const double n_rps = n_rpm / 60.0;
  const double axial = std::clamp(1.0 - t.c_th2 * axial_speed_mps / (n_rps * t.diameter_m), 0.0, 2.0);
  return static_thrust * forward_deduction * axial;
}

// Eq. 25: the thruster speed [rpm] that gives force T at rest (inverse of the
// static part of eq. 16).
inline double thrusterRpmForForce(const TunnelThruster& t, double rho, double force_n) {
  const double D2 = t.diameter_m * t.diameter_m;
  const double k = rho * D2 * D2 * t.KT_per_rpm2;
  return std::copysign(std::sqrt(std::abs(force_n) / k), force_n);
}

// Eq. 8-9: surge drag added by a running tunnel thruster whose jet speed is
// u_j = sqrt(4 F / (rho pi D^2)). `rho_vol23` = 0.5 rho V^(2/3).
inline double thrusterDragN(const ThrusterDragFit& f, double rho, double half_rho_vol23, double u,
                            double thrust_n, double diameter_m) {
  if (thrust_n == 0.0) return 0.0;
  const double uj = std::sqrt(4.0 * std::abs(thrust_n) / (rho * std::numbers::pi * diameter_m * diameter_m));
  const double r = std::abs(u) / uj;
  const double dCd = f.a1 * std::exp(-f.b1 * r) + f.a2 * std::exp(-f.b2 * r);
  return -half_rho_vol23 * std::abs(u) * u * dCd;
}

struct PlaneForces {
  double X_n = 0.0, Z_n = 0.0, M_nm = 0.0;
};

// Eq. 18-20, delta in degrees (paper sign).
inline PlaneForces sternPlaneForces(const SternPlanes& s, double u, double delta_deg) {
  const double uu = std::abs(u) * u;
  return {s.X_uudd_per_deg2 * uu * delta_deg * delta_deg, s.Z_uud_per_deg * uu * delta_deg,
          s.M_uud_per_deg * uu * delta_deg};
}

}  // namespace auv::sim
