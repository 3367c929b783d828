#pragma once
// A truth vehicle drawn away from the nominal profile, for proving the
// analysis where our own model cannot flatter it (issue 11): each group of
// hydrodynamic derivatives scaled, the Munk moment inside M_w or added on top,
// a propeller torque between none and twice nominal, and a ballast state the
// analysis must find. Deterministic per seed on every platform (mt19937_64
// with our own uniform mapping).
#include <cstdint>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "hydrostatics/mass_properties.h"
#include "sim/flown_mass.h"
#include "sim/vehicle_model.h"

namespace auv::sim {

struct TruthDrawRanges {
  double group_scale_min = 0.6, group_scale_max = 1.4;  // heave force, pitch moment, cross-flow
  double plane_min = 0.6, plane_max = 1.2;              // stern-plane effectiveness
  double munk_inside_probability = 0.5;
  double torque_factor_max = 2.0;  // propeller torque 0..max x nominal
  double bg_min_m = 0.012, bg_max_m = 0.030;
  double cg_x_max_m = 0.025, cg_y_max_m = 0.003;
  double net_min_kg = 1.0, net_max_kg = 8.0;
};

struct DrawnTruth {
  std::uint64_t seed = 0;
  double heave_scale = 1.0;      // Z_w', Z_q'
  double pitch_scale = 1.0;      // M_w', M_q'
  double crossflow_scale = 1.0;  // Z_|w|w, M_|w|w, M_|q|q
  double plane_scale = 1.0;      // stern-plane Z, M (and X) per degree
  bool munk_inside_Mw = false;   // true: no Munk moment on top of M_w
  double torque_factor = 1.0;    // K_Q0 multiplier
  // Ballast state of the first mission: CG relative to CB (BG = CG z), net
  // buoyancy (B - W)/g0 at the operating point, + = light.
  double bg_m = 0.02, cg_x_m = 0.0, cg_y_m = 0.0, net_buoyancy_kg = 0.0;

  std::string describe() const;
};

DrawnTruth drawTruth(std::uint64_t seed, const TruthDrawRanges& ranges = {});

// The nominal simulator model with the drawn hydrodynamics.
VehicleModel truthModel(const VehicleModel& nominal, const DrawnTruth& d);

// A companion document (resources/sim/<id>_hydrodynamics.json layout) with
// the drawn hydrodynamics, e.g. to hand a profile of the truth to a tool.
nlohmann::json truthHydrodynamicsDoc(const nlohmann::json& nominal_doc, const DrawnTruth& d);

// The ballast error that makes `truth` with `installed` weights fly with the
// drawn CG (x, y, BG) and net buoyancy, given the displaced mass [kg] at the
// operating point.
BallastError truthBallastError(const VehicleModel& truth, std::span<const MassItem> installed, double displaced_kg,
                               const DrawnTruth& d);

}  // namespace auv::sim
