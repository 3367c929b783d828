#pragma once
// Actuator states and their response to demands. An instant rpm or fin step is
// unphysical, so every actuator follows its demand through a first-order lag
// (solved exactly over the step) and a slew-rate limit. The simulator holds
// the result constant over one model step (zero-order hold at 20 Hz).
#include <array>

#include "sim/depth_autopilot.h"
#include "sim/vehicle_model.h"

namespace auv::sim {

struct ActuatorState {
  double prop_rps = 0.0;
  std::array<double, kMaxThrusters> thruster_rpm{};
  double plane_rad = 0.0;  // paper sign: positive = nose-up moment
  double plane_rate_radps = 0.0;
};

class ActuatorDynamics {
 public:
  ActuatorDynamics(const VehicleModel& model, double dt_s);

  // Move `state` one model step towards `demand`.
  void advance(ActuatorState& state, const ActuatorDemand& demand) const;

  // Demand after deadband and saturation (what the motor boards accept).
  double thrusterTargetRpm(int i, double demand_rpm) const;

 private:
  const VehicleModel* model_;
  double dt_;
  double alpha_prop_;
  std::array<double, kMaxThrusters> alpha_th_{};
};

}  // namespace auv::sim
