#pragma once
// Everything the simulator needs to know about one vehicle, SI inside. The body
// frame origin is the centre of buoyancy (as in the Delphin2 paper, sec. 3.1),
// x fwd, y stbd, z down. Angles inside are radians; the stern-plane derivatives
// keep the paper's per-degree form because that is how they were measured.
#include <array>
#include <string>

#include <Eigen/Core>

#include "vehicle/vehicle_profile.h"

namespace auv::sim {

struct RigidBody {
  double mass_kg = 0.0;
  Eigen::Vector3d r_g_m = Eigen::Vector3d::Zero();  // CG relative to CB
  Eigen::Vector3d cb_profile_m = Eigen::Vector3d::Zero();  // CB in the profile's frame
  double Ixx_kgm2 = 0.0;
  double Iyy_kgm2 = 0.0;
  HullModel hull;             // volume V(T, p) for the buoyancy
  double reference_length_m = 0.0;  // L in the nondimensional derivatives
};

// SNAME derivatives. The linear heave/pitch ones are speed dependent
// (Delphin2 App. A): Z_w = 0.5 rho L^2 u Z_w', Z_q = 0.5 rho L^3 u Z_q',
// M_w = 0.5 rho L^3 u M_w', M_q = 0.5 rho L^4 u M_q'.
struct Hydrodynamics {
  double Xudot_kg = 0.0;
  double Zwdot_kg = 0.0;
  double Mqdot_kgm2 = 0.0;
  double Kpdot_kgm2 = 0.0;
  double Xu_kg_per_s = 0.0;  // linear surge damping (Delphin2: none)
  double Xuu_kg_per_m = 0.0;
  double Zw_prime = 0.0, Zq_prime = 0.0, Mw_prime = 0.0, Mq_prime = 0.0;
  double Zww_kg_per_m = 0.0;
  double Zqq_kgm = 0.0;
  double Mww_kg = 0.0;
  double Mqq_kgm2 = 0.0;
  double Kp_kgm2_per_s = 0.0;  // linear roll damping
  double Kpp_kgm2 = 0.0;       // quadratic roll damping
  // Structure of the pitch moment in w: 1 adds the Munk moment (X_udot -
  // Z_wdot) u w of the added-mass Coriolis terms on top of M_w (the Fossen
  // form, the default); 0 takes it as already inside the tabulated M_w, as
  // when M_w comes from a captive-model test of the whole hull. A truth drawn
  // away from the profile uses either (sim/truth_draw.h).
  double munk_factor = 1.0;
};

// Main propeller, eq. 11-14, plus a reaction torque for roll.
struct Propeller {
  double KT0 = 0.0;
  double diameter_m = 0.0;
  double c1 = 1.0, c2 = 1.0;  // K_T = K_T0 (1 - (J/c1)^c2)
  double wake_fraction = 0.0;
  double thrust_deduction = 0.0;
  // n [rev/s] = a2 d^2 + a1 d + a0 for demand d (eq. 13), clipped at 0.
  double rps_a2 = 0.0, rps_a1 = 0.0, rps_a0 = 0.0;
  double max_demand = 0.0;
  double KQ0 = 0.0;          // torque coefficient at J = 0 (assumption, roll only)
  double torque_sign = 1.0;  // +1: reaction torque rolls starboard down
  double time_constant_s = 0.5;
  double max_rate_rps_per_s = 10.0;
};

// Through-body tunnel thruster, eq. 16. n in rpm because K_T,th is per rpm^2.
struct TunnelThruster {
  double x_m = 0.0;  // along the body axis from CB
  double diameter_m = 0.0;
  double KT_per_rpm2 = 0.0;  // static thrust = rho |n| n D^4 K_T
  double c_th1_s2_per_m2 = 0.0;
  double c_th2 = 0.0;
  double deadband_rpm = 0.0;
  double max_rpm = 0.0;
  double time_constant_s = 0.2;
};

// Volumetric drag increment of a running tunnel thruster, eq. 8.
struct ThrusterDragFit {
  double a1 = 0.0, b1 = 0.0, a2 = 0.0, b2 = 0.0;  // dCd = a1 exp(-b1 r) + a2 exp(-b2 r)
};

// Stern planes, eq. 18-20, derivatives per degree of deflection. Positive
// deflection (paper) = downward force at the stern = nose-up moment.
struct SternPlanes {
  double X_uudd_per_deg2 = 0.0;
  double Z_uud_per_deg = 0.0;
  double M_uud_per_deg = 0.0;
  double max_deg = 30.0;
  double rate_deg_per_s = 40.0;
};

// Electrical power, the quantity of the paper's Tables 1-2.
struct PowerModel {
  double hotel_w = 0.0;
  double prop_w_per_rps2 = 0.0;          // P = k n^2, n in rev/s
  double thruster_w_per_rpm3 = 0.0;      // P = idle + k |n|^3
  double thruster_idle_w = 0.0;
  double fins_idle_w = 0.0;
  double fins_w_per_m2s2_deg = 0.0;      // P = idle + k u^2 |delta|
};

// Yaw of an axisymmetric hull with a cruciform tail, taken by symmetry from
// the pitch plane (I_zz = I_yy, N_rdot = M_qdot, N_r' = M_q', N_|r|r = M_|q|q,
// rudder = stern planes): the derivatives we have, no invented ones. Sway is
// neglected (v = 0) and yaw has no restoring moment, so heading is decoupled
// from the vertical plane (docs/decisions/sim-heading.md). Rudder angle in the
// interchange-log sign: trailing edge to starboard positive, which turns the
// bow to starboard (heading increases).
struct YawModel {
  double Izz_kgm2 = 0.0;
  double Nrdot_kgm2 = 0.0;
  double Nr_prime = 0.0;        // N_r = 0.5 rho L^4 |u| N_r'
  double Nrr_kgm2 = 0.0;        // N_|r|r
  double N_uud_per_deg = 0.0;   // yaw moment per (m/s)^2 per degree of rudder, > 0
  double rudder_max_deg = 30.0;
  double rudder_rate_deg_per_s = 40.0;
};

inline constexpr int kMaxThrusters = 2;

struct VehicleModel {
  std::string id;
  RigidBody body;
  Hydrodynamics hydro;
  Propeller prop;
  std::array<TunnelThruster, kMaxThrusters> thrusters{};  // [0] front, [1] aft
  int thruster_count = 0;
  ThrusterDragFit thruster_drag;
  SternPlanes planes;
  YawModel yaw;
  PowerModel power;
};

}  // namespace auv::sim
