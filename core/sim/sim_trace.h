#pragma once
// What a simulated mission leaves behind: one array per channel on a common
// time base (struct of arrays, SI units), named after the interchange-log
// channels (docs: ../shared/formats/mission-log-csv.md) so that the log writer
// can map them one to one. Depth/pitch/roll/speed are the measured values
// (with sensor noise, if any), like a vehicle's own log.
#include <cstddef>
#include <limits>
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
  std::vector<double> heading_rad, heading_cmd_rad;  // 0..2 pi; cmd NaN without heading hold
  std::vector<double> rudder_rad;                    // log sign: positive turns to starboard
  // Gliders only (empty for propeller-driven vehicles).
  std::vector<double> pump_volume_m3;      // buoyancy engine, relative to its zero
  std::vector<double> battery_position_m;  // pitch battery, positive = forward (nose down)
  std::vector<double> roll_mass_rad;

  // The vehicle as flown (after installed weights, trims and ballast error),
  // for writing into a log so that an analysis can be checked against it.
  struct Truth {
    double mass_kg = 0.0;
    double cg_x_m = 0.0, cg_y_m = 0.0, cg_z_m = 0.0;  // CG relative to CB, body axes
    double hull_volume_m3 = 0.0;                      // V0 of the hull model
    double net_buoyancy_start_n = 0.0;                // B - W at the first sample
    // Gliders: g (rho V_hull(T, p) - m) with the pump at zero, averaged over
    // the samples deeper than 10 m (what a steady-glide fit estimates).
    double net_buoyancy_pump0_mean_n = std::numeric_limits<double>::quiet_NaN();
  } truth;

  // Whole-run totals, integrated every model step (not from the samples).
  double energy_j = 0.0;
  double hotel_energy_j = 0.0, prop_energy_j = 0.0, thruster_energy_j = 0.0, fins_energy_j = 0.0;

  std::size_t size() const { return time_s.size(); }
  void reserve(std::size_t n);
  void clear();
};

}  // namespace auv::sim
