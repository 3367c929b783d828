#pragma once
// One model step of the simulated vehicle, shared by plan simulation and log
// replay: water and buoyancy at the current depth, the measurements the
// autopilot and the log see, the RK4 step of the dynamics with the actuators
// held (zero-order hold at the model rate), the heading beside it, and the
// actuators moving towards their demands. Owns no storage that grows: the
// loops that drive it stay free of allocation.
#include <array>
#include <optional>

#include "sim/actuator_state.h"
#include "sim/dynamics.h"
#include "sim/flown_mass.h"
#include "sim/heading_control.h"
#include "sim/power_model.h"
#include "sim/sensor_noise.h"
#include "sim/sim_trace.h"
#include "sim/water_column.h"

namespace auv::sim {

// B = rho(z) g V(T, p), with the emerged part of the hull section removed
// when `surface_model` is on: the same HullModel::volumeAt and in-situ
// density (core seawater, tabulated) that core hydrostatics uses.
double buoyancyN(const VehicleModel& model, const WaterSample& water, double depth_m, bool surface_model);

struct InitialState {
  double depth_m = 0.0;
  double pitch_rad = 0.0;
  double roll_rad = 0.0;
  double heading_rad = 0.0;
  double speed_mps = 0.0;
  double prop_rps = 0.0;
  // A start in motion (a replay from a logged row mid-dive): the depth rate
  // through the water [m/s, down positive] sets the heave velocity; the
  // planes and thrusters start where they were. Unset: at rest in heave.
  std::optional<double> depth_rate_mps;
  double plane_rad = 0.0;  // paper sign: positive = nose-up moment
  std::array<double, kMaxThrusters> thruster_rpm{};
};

// What the trace records besides the state: set points and controller outputs.
struct SampleExtras {
  double depth_cmd_m = 0.0;
  double pitch_cmd_rad = 0.0;
  double heading_cmd_rad = 0.0;  // NaN without heading hold
  double hover_force_n = 0.0;
};

class StepEngine {
 public:
  StepEngine(const VehicleModel& model, const WaterColumn& water, double dt_s, bool surface_model);

  // Start state and the mass as flown (the net-buoyancy trim uses the
  // buoyancy at the start depth).
  void start(const InitialState& init, const VehicleLoading& loading);

  // Water and buoyancy at the current depth: once per step, before the rest.
  void sampleWater();
  const WaterSample& water() const { return ws_; }
  double buoyancyN() const { return B_; }
  double weightN() const { return W0_; }  // as flown, before buoyancy events
  const FlownMass& mass() const { return fm_; }

  // Depth, depth rate, pitch, pitch rate, speed with sensor noise.
  Measurement measure(GaussianSource& noise, const SensorNoise& sigma) const;
  double headingMeasured(GaussianSource& noise, const SensorNoise& sigma) const {
    return yaw_.heading_rad + noise.next(sigma.heading_rad);
  }

  // Appends one sample; `weight_n` is the weight now (events included).
  void record(SimTrace& tr, double t, const Measurement& meas, const SampleExtras& extras, double weight_n,
              GaussianSource& noise, const SensorNoise& sigma) const;

  // Integrates one step with the actuators held, then moves them towards the
  // demands (plan simulation) ...
  void step(double weight_n, const ActuatorDemand& demand, double rudder_demand_rad);
  // ... or leaves them as set through actuators()/yaw() (replay).
  void stepHeld(double weight_n);

  StateVector& state() { return s_; }
  const StateVector& state() const { return s_; }
  ActuatorState& actuators() { return act_; }
  YawState& yaw() { return yaw_; }
  const YawState& yaw() const { return yaw_; }

  // Whole-run energy and the vehicle as flown, into the trace.
  void finish(SimTrace& tr) const;

 private:
  const VehicleModel* model_;
  const WaterColumn* waterColumn_;
  double dt_;
  bool surface_;
  Dynamics dyn_;
  ActuatorDynamics actDyn_;
  YawConstants yawK_;
  StateVector s_ = StateVector::Zero();
  ActuatorState act_;
  YawState yaw_;
  FlownMass fm_;
  double W0_ = 0.0, B_ = 0.0, B_start_ = 0.0;
  double t_s_ = 0.0;  // time since start, for a moving water column
  WaterSample ws_;
  double energy_j_ = 0.0, hotel_j_ = 0.0, prop_j_ = 0.0, thruster_j_ = 0.0, fins_j_ = 0.0;
};

}  // namespace auv::sim
