#pragma once
// Concealed-effect recordings of an AUV for proving the model check: the
// simulator (sim::simulate, the same autopilot and sensor noise as any plan)
// flies a mission of depth steps at several propeller speeds with a ballast
// error and one "truth" effect the analysis model lacks:
//   hull compressibility / thermal expansion   -> the model's hull
//   propeller_torque                           -> extra K_Q0 of the propeller
//   quadratic_pitch_damping                    -> M_|q|q scaled
//   mass_drift                                 -> buoyancy steps every 10 s
//   pitch/roll sensor bias, depth offset       -> the autopilot steers on the
//     biased reading (legs shifted), the log records it (added afterwards)
// The log carries the truth in its metadata (sim_log.h plus truth_* terms).
#include <cstdint>
#include <vector>

#include "missionlog/mission_log.h"
#include "sim/mission_plan.h"
#include "sim/simulator.h"

namespace auv::discrepancy {

struct SyntheticAuvTruth {
  sim::BallastError ballast_error;  // net buoyancy [kg] and CG shift [m]
  double extra_compressibility_per_dbar = 0.0;
  double extra_thermal_expansion_per_degC = 0.0;
  double extra_prop_KQ0 = 0.0;       // added to the signed K_Q0
  double pitch_damping_scale = 0.0;  // M_|q|q -> (1 + s) M_|q|q
  double mass_drift_kg_per_h = 0.0;
  double pitch_bias_deg = 0.0, roll_bias_deg = 0.0, depth_offset_m = 0.0;
};

struct SyntheticAuvMission {
  std::vector<sim::DepthLeg> legs;  // empty = the default mission (depth steps at three speeds)
  double leg_s = 240.0;             // default mission: leg length
  int legs_count = 15;
  std::vector<double> depths_m = {6.0, 14.0, 9.0, 20.0, 4.0};
  std::vector<double> prop_demands = {14.0, 20.0, 26.0};
  std::vector<sim::CtdPoint> cast = {{0.0, 14.0, 34.0}, {8.0, 12.0, 34.5}, {15.0, 9.0, 35.0}, {40.0, 8.0, 35.1}};
  double trace_interval_s = 0.2;
  // The emerged hull loses its buoyancy (sim::SimOptions::surface_model): a
  // vehicle too buoyant to hold depth floats at the surface instead of
  // climbing on through a sea that is not there.
  bool surface_model = false;
  sim::SensorNoise noise;  // default: depth 1 cm, pitch 0.05 deg, roll 0.05 deg, speed 1 cm/s, T 2 mK, S 3e-3, p 0.01 dbar
  std::uint64_t seed = 1;
  bool default_noise = true;
};

// The truth effects on a vehicle model (hull, propeller torque, M_|q|q), on
// a scenario (legs steered on a biased reading, the mass drift as buoyancy
// steps over `duration_s`), and on its log (the biased readings recorded).
// Shared with the HUGIN survey harness, which flies drawn truths.
void applyTruthEffects(sim::VehicleModel& model, const SyntheticAuvTruth& truth);
void applyTruthEffects(sim::Scenario& scenario, const SyntheticAuvTruth& truth, double duration_s);
void recordSensorBiases(MissionLog& log, const SyntheticAuvTruth& truth);

// `vehicle` is the analysis model (loadSimVehicle of the profile); the truth
// is this model with the truth effects added.
MissionLog synthesizeAuvLog(const sim::SimVehicle& vehicle, const std::string& vehicle_id, const SyntheticAuvTruth& truth,
                            const SyntheticAuvMission& mission);

}  // namespace auv::discrepancy
