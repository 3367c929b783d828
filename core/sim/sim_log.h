#pragma once
// A simulated mission as a mission log (shared/formats/mission-log-csv.md):
// the channels a vehicle logs, in the format's units and signs, and metadata
// saying where it came from and what the vehicle really was, so that an
// analysis of the log can be checked against the truth:
//   # vehicle: hugin1000
//   # source: auvballast simulate
//   # mode: plan | replay          # plan: <file>  or  # replay_of: <file>
//   # seed: 2026
//   # truth_net_buoyancy_kg: ...   (B - W)/g0 at the first sample, + = light
//   # truth_net_buoyancy_mean_kg:  the same averaged over the logged samples
//   # truth_cg_x_mm, _y_mm, _z_mm: CG relative to CB, body axes (x fwd, y stbd, z down)
//   # truth_mass_kg, truth_hull_volume_m3, installed_kg: FS,FP,...
//   # truth_net_buoyancy_pump0_mean_kg: gliders, rho V_hull - m with the pump
//     at zero averaged below 10 m (the number a steady-glide fit estimates)
// Gliders log pump_volume [cm3], battery_position [mm] (+ = forward, nose
// down) and roll_mass [deg] instead of speed, propeller and fins.
// Noise and output rate are those of the simulation (SimOptions::noise,
// trace_interval_s), so a given seed always writes the same file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "missionlog/mission_log.h"
#include "sim/sim_trace.h"

namespace auv::sim {

struct SimLogInfo {
  std::string vehicle;        // profile id
  std::string mode = "plan";  // "plan" or "replay"
  std::string input;          // the plan file, or the replayed log
  std::uint64_t seed = 0;
  int thruster_count = 0;     // > 0: also thruster_front_rpm / thruster_aft_rpm [rpm]
  std::vector<double> installed_kg;
  std::vector<MetadataEntry> extra;  // appended after ours
};

MissionLog toMissionLog(const SimTrace& trace, const SimLogInfo& info);

// Where the log was flown, for SimLogInfo::extra: "latitude" in the header, so
// the analysis converts pressure to depth with the gravity the simulator's
// water column used (without it, 45 deg: a 60 deg log's depth and pressure
// then disagree by 0.13 %, which the model check read as a depth offset).
MetadataEntry latitudeMetadata(double latitude_deg);

// toMissionLog + writeInterchangeCsv. Throws InputError if it cannot write.
void writeSimulatedLog(const SimTrace& trace, const SimLogInfo& info, const std::filesystem::path& path);

// Shortest text that reads back to the same double.
std::string formatNumber(double v);

}  // namespace auv::sim
