#pragma once
// What a simulated mission leaves behind: one array per channel on a common
// time base (struct of arrays, SI units), named after the interchange-log
// channels (docs: ../shared/formats/mission-log-csv.md) so that the log writer
// can map them one to one. Depth/pitch/roll/speed are the measured values
// (with sensor noise, if any), like a vehicle's own log.
#include <cstddef>
#include <vector>

namespace auv::sim {

struct SimTrace {
  std::vector<double> time_s;
  std::vector<double> depth_m, depth_cmd_m;
  std::vector<double> pitch_rad, pitch_cmd_rad, roll_rad;
  std::vector<double> speed_mps;     // surge speed through water
  std::vector<double> x_m;           // distance along track
  std::vector<double> prop_rpm;
  std::vector<double> elevator_rad;  // log sign: trailing edge down positive
  std::vector<double> thruster_front_rpm, thruster_aft_rpm;
  std::vector<double> power_w;       // total electrical
  std::vector<double> power_prop_w, power_thruster_front_w, power_thruster_aft_w, power_fins_w;
  std::vector<double> net_buoyancy_n;  // B - W as flown (true, not measured)
  std::vector<double> hover_force_n;   // eq. 22 output
  std::vector<double> temperature_degC, salinity_psu, pressure_dbar;

  // Whole-run totals, integrated every model step (not from the samples).
  double energy_j = 0.0;
  double hotel_energy_j = 0.0, prop_energy_j = 0.0, thruster_energy_j = 0.0, fins_energy_j = 0.0;

  std::size_t size() const { return time_s.size(); }
  void reserve(std::size_t n);
  void clear();
};

}  // namespace auv::sim
