#pragma once
// Steady level flight of a propeller-driven AUV in the vertical plane, the
// same force model as the simulator (Delphin2 paper eq. 1-5, Fossen form,
// origin at the centre of buoyancy) with q = 0 and u_dot = w_dot = 0:
//
//   heave:  (B - W) cos(theta) cos(phi) = Z_h
//   pitch:  W (BG sin(theta) + x_G cos(theta) cos(phi)) = M_h
//
//   Z_h = k_Zw |u| w + Z_ww |w| w + Z_e |u| u e
//   M_h = k_Mw u w + M_ww |w| w + (X_udot - Z_wdot) u w + M_e |u| u e
//   k_Zw = rho L^2 Z_w'/2,  k_Mw = rho L^3 M_w'/2,  w = (u sin(theta) + z_dot) / (cos(theta) cos(phi))
//
// e is the elevator angle in the interchange-log convention (trailing edge
// down positive, degrees); profile derivatives in the opposite convention are
// converted on load (docs/decisions/analysis-elevator-sign.md).
#include <optional>
#include <string>

#include "common/message.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis {

struct SteadyHydroCoefficients {
  double reference_length_m = 0.0;
  double Zw_prime = 0.0, Mw_prime = 0.0;
  double Zww_kg_per_m = 0.0, Mww_kg = 0.0;
  double Xudot_kg = 0.0, Zwdot_kg = 0.0;
  // Munk moment (X_udot - Z_wdot) u w: 1 on top of M_w (the simulator's
  // default Fossen form), 0 inside the tabulated M_w ("munk_moment":
  // "inside_Mw"). munk_stated: the profile said which.
  double munk_factor = 1.0;
  bool munk_stated = false;
  bool has_planes = false;
  double Z_e_per_deg = 0.0;  // N per (m/s)^2 per degree, interchange sign
  double M_e_per_deg = 0.0;  // N m per (m/s)^2 per degree, interchange sign
  Message note;              // e.g. the sign conversion applied
};

// From the profile's "hydrodynamics" section (and "actuators.stern_planes" or
// plane derivatives inside "hydrodynamics"); nullopt with `why_not` filled when
// the profile has none. Malformed values throw InputError naming the field.
std::optional<SteadyHydroCoefficients> steadyHydroFromProfile(const VehicleProfile& v, std::string& why_not);

struct SteadyFlight {
  double speed_mps = 0.0;
  double pitch_rad = 0.0;
  double roll_rad = 0.0;
  double elevator_deg = 0.0;
  double depth_rate_mps = 0.0;  // positive descending
  double density_kgm3 = 1025.0;
};

struct HydroLoads {
  double Z_lift = 0.0, Z_planes = 0.0;                  // N, body z down
  double M_lift = 0.0, M_munk = 0.0, M_planes = 0.0;    // N m, nose up
  double Z() const { return Z_lift + Z_planes; }
  double M() const { return M_lift + M_munk + M_planes; }
};

HydroLoads steadyHydroLoads(const SteadyHydroCoefficients& c, const SteadyFlight& f);

// The products the balance is linear in (w from the heave kinematics above,
// e in degrees). Over an oscillation the balance of the means holds for the
// means of these products, not for the products of the means (|w| w, u w
// and u^2 e swing together), so an averaged leg carries their cycle means.
struct BalanceRegressors {
  double cc = 1.0;         // cos(theta) cos(phi)
  double sin_theta = 0.0;
  double au_w = 0.0;       // |u| w
  double u_w = 0.0;        // u w
  double aw_w = 0.0;       // |w| w
  double au_u = 0.0;       // |u| u
  double au_u_e = 0.0;     // |u| u e
};
BalanceRegressors balanceRegressors(const SteadyFlight& f);

}  // namespace auv::analysis
