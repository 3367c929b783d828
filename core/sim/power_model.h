#pragma once
// Electrical power drawn by the vehicle (hotel + actuators), the quantity of
// the Delphin2 paper's Tables 1-2, and what a ballast error costs in watts.
#include "sim/actuator_state.h"
#include "sim/vehicle_model.h"

namespace auv::sim {

struct PowerBreakdown {
  double hotel_w = 0.0;
  double prop_w = 0.0;
  std::array<double, kMaxThrusters> thruster_w{};
  double fins_w = 0.0;
  double total_w = 0.0;
};

PowerBreakdown electricalPower(const VehicleModel& model, const ActuatorState& a, double speed_mps);

// Power the tunnel thrusters need to hold a vehicle of net buoyancy B - W
// [N] at zero speed, CG under CB, force shared by the lever rule about x_cr:
// the steady-state P_B of the paper's eq. 39 at u = 0.
double hoverHoldPowerW(const VehicleModel& model, double net_buoyancy_n, double water_density_kgm3,
                       double x_cr_m = 0.0);

}  // namespace auv::sim
