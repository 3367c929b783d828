#pragma once
// Flies a scenario: fixed-step RK4 of the vehicle dynamics at the model rate
// (paper: 20 Hz), the depth autopilot at its own sample rate (paper: 5 Hz),
// actuators following their demands with lags and rate limits, buoyancy from
// the water column at the current depth. Everything the step loop needs is
// sized before it starts; the loop itself does not allocate.
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "hydrostatics/mass_properties.h"
#include "sim/depth_autopilot.h"
#include "sim/flown_mass.h"
#include "sim/sensor_noise.h"
#include "sim/sim_trace.h"
#include "sim/vehicle_model.h"
#include "sim/water_column.h"

namespace auv::sim {

// Hold a depth at a propeller demand for a while (the paper's test legs).
struct DepthLeg {
  double duration_s = 0.0;
  double depth_m = 0.0;
  double prop_demand = 0.0;
  double pitch_rad = 0.0;
  // Heading set point (0..2 pi); NaN keeps the previous leg's (or the
  // initial) heading. Used only by a vehicle with heading hold.
  double heading_rad = std::numeric_limits<double>::quiet_NaN();
  // The depth command moves linearly from the previous leg's depth (the
  // initial depth for the first leg) to depth_m over the leg, as a vehicle's
  // guidance ramps a depth change; false = a step at the leg's start.
  // A ramp built from 1-s step legs instead steps the command on every
  // sample of a 1 Hz log, and each sample catches the autopilot's kick at
  // the same phase: the logged elevator means of the glide are biased.
  bool ramp = false;
};

// A sudden change of net buoyancy, e.g. a weight dropped on or taken off
// (sec. 8.4) or a salinity front. Positive = more buoyant. Acts at the CG.
struct BuoyancyChange {
  double time_s = 0.0;
  double delta_n = 0.0;
};

struct Scenario {
  std::vector<DepthLeg> legs;
  std::vector<BuoyancyChange> buoyancy_changes;  // any order
  // Ballast as installed relative to the profile's reference configuration,
  // positions in the profile's frame (what the ballast tools produce):
  // installed adjustment weights (installedWeights) and other changes.
  std::vector<MassItem> extra_masses;
  // If set: trim the weight (a mass at the CG) so that B - W equals this at
  // the start depth, as when a vehicle is ballasted in the test tank.
  std::optional<double> net_buoyancy_n;
  // Applied after the above: the known error a round-trip test recovers.
  BallastError ballast_error;
  double initial_depth_m = 0.0;
  double initial_pitch_rad = 0.0;
  double initial_roll_rad = 0.0;
  double initial_heading_rad = 0.0;
  double initial_speed_mps = 0.0;  // > 0: also starts the propeller at the first leg's demand

  VehicleLoading loading() const { return {extra_masses, net_buoyancy_n, ballast_error}; }
};

struct SimOptions {
  double dt_s = 0.05;              // paper: 20 Hz
  double trace_interval_s = 0.2;   // one sample per controller step
  bool preload_hover_integrator = true;  // paper sec. 7
  // Reduce buoyancy by the emerged part of the hull cross-section when the
  // vehicle breaks the surface. Off reproduces the paper's model (no surface).
  bool surface_model = false;
  SensorNoise noise;
  std::uint64_t seed = 1;
};

SimTrace simulate(const VehicleModel& model, const DepthAutopilotConfig& autopilot, const WaterColumn& water,
                  const Scenario& scenario, const SimOptions& options = {});

// Total duration of the legs.
double scenarioDuration(const Scenario& scenario);

// Submerged fraction of a circular hull section of diameter d whose axis is
// at depth z (z < -d/2: in the air, z > d/2: fully submerged).
double submergedFraction(double z_m, double diameter_m);

}  // namespace auv::sim
