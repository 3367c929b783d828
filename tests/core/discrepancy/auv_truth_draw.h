#pragma once
// A truth vehicle drawn away from the profile, for proving the model check
// where our own model cannot flatter us (issue 11): the simulator with the
// vehicle's hydrodynamic groups scaled by factors the analysis does not know.
// (A minimal drawing of our own: core/sim/truth_draw of the calibration work
// had not landed when this was written; it draws the same groups.)
//   heave derivatives Z_w', Z_q', Z_ww       x U(0.6, 1.4)
//   pitch derivatives M_w', M_ww             x U(0.6, 1.4), and the Munk
//     moment inside the tabulated M_w' (half the draws: M_w' - Munk') or on
//     top (the simulator adds it through the Coriolis terms)
//   pitch damping M_q'                       x U(0.6, 1.4)
//   roll damping K_p, K_|p|p                 x U(0.6, 1.4)
//   surge drag X_uu                          x U(0.6, 1.4)
//   stern-plane effectiveness X/Z/M_uud      x U(0.6, 1.2)
//   propeller torque K_Q0                    x U(0, 2) (or exactly 0)
//   ballast: net buoyancy U(0.1, 0.6) kg, CG x U(-3, 3) mm, CG y U(-0.6, 0.6) mm
// M_|q|q is left at the profile's: the concealed quadratic pitch damping is
// the only thing that changes it.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "sim/mission_plan.h"
#include "sim/simulator.h"

namespace auv::discrepancy::test {

struct DrawnAuvTruth {
  sim::SimVehicle vehicle;          // the truth's model (the analysis keeps the profile's)
  sim::BallastError ballast_error;
  double heave_scale = 1.0, pitch_scale = 1.0, pitch_damping_scale = 1.0, roll_damping_scale = 1.0;
  double drag_scale = 1.0, plane_scale = 1.0, torque_scale = 1.0;
  bool munk_inside = false;
  std::string describe() const {
    char b[256];
    std::snprintf(b, sizeof b, "Z %.2f M %.2f%s Mq %.2f K %.2f X %.2f planes %.2f torque %.2f nb %.2f kg cg %.1f/%.2f mm",
                  heave_scale, pitch_scale, munk_inside ? " (Munk inside)" : "", pitch_damping_scale, roll_damping_scale,
                  drag_scale, plane_scale, torque_scale, ballast_error.net_buoyancy_kg, 1e3 * ballast_error.cg_shift_m.x(),
                  1e3 * ballast_error.cg_shift_m.y());
    return b;
  }
};

// `zero_torque`: the truth's propeller makes no reaction torque at all.
inline DrawnAuvTruth drawAuvTruth(const sim::SimVehicle& nominal, std::uint64_t seed, bool zero_torque = false) {
  std::mt19937_64 rng(seed * 7919u + 17u);
  auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  DrawnAuvTruth t;
  t.vehicle = nominal;
  sim::VehicleModel& m = t.vehicle.model;
  t.heave_scale = U(0.6, 1.4);
  t.pitch_scale = U(0.6, 1.4);
  t.munk_inside = U(0.0, 1.0) < 0.5;
  t.pitch_damping_scale = U(0.6, 1.4);
  t.roll_damping_scale = U(0.6, 1.4);
  t.drag_scale = U(0.6, 1.4);
  t.plane_scale = U(0.6, 1.2);
  t.torque_scale = zero_torque ? 0.0 : U(0.0, 2.0);
  m.hydro.Zw_prime *= t.heave_scale;
  m.hydro.Zq_prime *= t.heave_scale;
  m.hydro.Zww_kg_per_m *= t.heave_scale;
  m.hydro.Mw_prime *= t.pitch_scale;
  m.hydro.Mww_kg *= t.pitch_scale;
  if (t.munk_inside) {
    // The tabulated M_w already holds the Munk moment (X_udot - Z_wdot) u w,
    // which the simulator adds again: take it out of the derivative.
    const double L = m.body.reference_length_m;
    m.hydro.Mw_prime -= (m.hydro.Xudot_kg - m.hydro.Zwdot_kg) / (0.5 * 1025.0 * L * L * L);
  }
  m.hydro.Mq_prime *= t.pitch_damping_scale;
  m.hydro.Kp_kgm2_per_s *= t.roll_damping_scale;
  m.hydro.Kpp_kgm2 *= t.roll_damping_scale;
  m.hydro.Xuu_kg_per_m *= t.drag_scale;
  m.planes.X_uudd_per_deg2 *= t.plane_scale;
  m.planes.Z_uud_per_deg *= t.plane_scale;
  m.planes.M_uud_per_deg *= t.plane_scale;
  m.prop.KQ0 *= t.torque_scale;
  t.ballast_error.net_buoyancy_kg = U(0.1, 0.6);
  t.ballast_error.cg_shift_m = Eigen::Vector3d(U(-0.003, 0.003), U(-0.0006, 0.0006), 0.0);
  return t;
}

}  // namespace auv::discrepancy::test
