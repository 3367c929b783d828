#pragma once
// Re-simulating a recording with library terms switched on. The model
// parameters a term changes (hull compressibility and thermal expansion,
// propeller reaction torque, quadratic pitch damping) go into a copy of the
// sim::VehicleModel; the rest need hooks in the step loop that sim::replay
// does not have: a weight that drifts with time, a vertical current moving
// the vehicle over ground, and sensor errors seen by the autopilot and the
// log (pitch/roll bias, depth offset). The loop is sim::replay's (same
// StepEngine, grid, drives and autopilot); with no hooks active it gives the
// same trace, which a test checks (docs/decisions/model-check-replay.md).
#include <limits>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "discrepancy/physics_terms.h"
#include "missionlog/mission_log.h"
#include "sim/depth_autopilot.h"
#include "sim/flown_mass.h"
#include "sim/replay.h"
#include "sim/sensor_noise.h"
#include "sim/vehicle_model.h"
#include "sim/water_column.h"

namespace auv::discrepancy {

// The model with the parameter-type terms applied (a copy).
sim::VehicleModel adjustedModel(const sim::VehicleModel& model, const SimAdjustment& a);

// Extra propeller K_Q0 (signed, the sim's torque_sign times K_Q0) for a torque
// coefficient [N m / rpm^2] at bollard pull in water of 1025 kg/m3.
double propKQ0ForTorque(const sim::Propeller& p, double nm_per_rpm2);

struct TermReplayOptions {
  sim::ReplayDrive drive = sim::ReplayDrive::DepthCommands;
  double dt_s = 0.05;
  sim::VehicleLoading loading;
  bool preload_hover_integrator = true;  // as a simulated mission starts (sim::simulate)
  double mass_reference_time_s = 0.0;    // the drifting mass equals the loading's at this time
  // > 0: restart from the logged state this often (a short-horizon replay:
  // the water's unlogged motion and the autopilot's reaction to sensor noise
  // do not accumulate into phase errors that no model can reproduce).
  double restart_every_s = 0.0;
  // Rows with a logged depth shallower than this, for at least the drop-out
  // length (below), are a surface interval: the model has no surface (no
  // emerged hull, no waves, no surface behaviour), so it does not fly them;
  // the replay ends before and restarts from the logged state after, as at a
  // drop-out. -inf: never.
  double surface_depth_m = -std::numeric_limits<double>::infinity();
  // The emerged hull loses its buoyancy (sim::SimOptions::surface_model): a
  // replay that breaks the surface floats there, as the vehicle did.
  bool surface_model = false;
  // Sensor noise the replayed autopilot steers on and the trace records
  // (a noise twin of the log: model_check.h); zero = exact readings. Each
  // span draws from its own stream of `noise_seed`.
  sim::SensorNoise noise;
  std::uint64_t noise_seed = 0;
};

// Simulated sensor readings at `times` (ascending, within the log).
struct TermReplayTrace {
  std::vector<double> depth_m, pitch_rad, roll_rad, speed_mps, vertical_velocity_mps;  // vv up positive, over ground
  std::vector<double> elevator_deg, pressure_dbar;  // the plane as logged (log sign), the CTD's pressure
  std::vector<double> thruster_front_rpm, thruster_aft_rpm;  // tunnel thrusters (0 without)
  std::vector<double> pitch_cmd_deg;  // the replayed autopilot's pitch demand (depth-command drive only, else NaN)
  std::vector<double> since_start_s;  // time since the replay (re)started from the log; NaN where not flown
};

TermReplayTrace termReplay(const sim::VehicleModel& model, const sim::DepthAutopilotConfig& autopilot,
                           const sim::WaterColumn& water, const MissionLog& recorded, const SimAdjustment& terms,
                           std::span<const double> times, const TermReplayOptions& options);

}  // namespace auv::discrepancy
