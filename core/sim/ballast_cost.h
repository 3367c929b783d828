#pragma once
// What a ballast error costs the operator: the extra electrical power the
// vehicle spends holding depth because it is not neutral (the P_B of the
// Delphin2 paper's eq. 39), found by flying the same leg twice, once with the
// given net buoyancy and once neutral, and comparing the settled averages.
#include "sim/depth_autopilot.h"
#include "sim/vehicle_model.h"
#include "sim/water_column.h"

namespace auv::sim {

struct BallastErrorCost {
  double power_w = 0.0;            // mean total electrical power with the error
  double neutral_power_w = 0.0;    // same leg, neutrally buoyant
  double extra_power_w = 0.0;      // power_w - neutral_power_w
  double mean_pitch_rad = 0.0;     // attitude the vehicle flies with the error
  double mean_speed_mps = 0.0;
  double extra_energy_per_hour_wh = 0.0;  // = extra_power_w * 1 h
};

// Holds `depth_m` at `prop_demand` for settle_s + average_s seconds and
// averages over the last average_s. Positive net buoyancy = too light.
BallastErrorCost ballastErrorCost(const VehicleModel& model, const DepthAutopilotConfig& autopilot,
                                  const WaterColumn& water, double net_buoyancy_n, double prop_demand,
                                  double depth_m = 2.0, double settle_s = 120.0, double average_s = 120.0);

}  // namespace auv::sim
