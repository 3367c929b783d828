#include "sim/sim_trace.h"

namespace auv::sim {
namespace {

template <class F>
void forEachChannel(SimTrace& t, F&& f) {
  for (auto* v : {&t.time_s, &t.depth_m, &t.depth_cmd_m, &t.pitch_rad, &t.pitch_cmd_rad, &t.roll_rad,
                  &t.speed_mps, &t.x_m, &t.prop_rpm, &t.elevator_rad, &t.thruster_front_rpm,
                  &t.thruster_aft_rpm, &t.power_w, &t.power_prop_w, &t.power_thruster_front_w,
                  &t.power_thruster_aft_w, &t.power_fins_w, &t.net_buoyancy_n, &t.hover_force_n,
                  &t.temperature_degC, &t.salinity_psu, &t.pressure_dbar, &t.heading_rad,
                  &t.heading_cmd_rad, &t.rudder_rad, &t.pump_volume_m3, &t.battery_position_m, &t.roll_mass_rad}) {
    f(*v);
  }
}

}  // namespace

void SimTrace::reserve(std::size_t n) {
  forEachChannel(*this, [n](std::vector<double>& v) { v.reserve(n); });
}

void SimTrace::clear() {
  forEachChannel(*this, [](std::vector<double>& v) { v.clear(); });
  energy_j = hotel_energy_j = prop_energy_j = thruster_energy_j = fins_energy_j = 0.0;
  truth = {};
}

}  // namespace auv::sim
