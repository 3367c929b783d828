#pragma once
// Replay: fly the model with what a recording says the vehicle did, so a
// recorded (or simulated) mission can be re-simulated step for step and the
// two compared channel by channel (the model check). The propeller always
// runs at the logged prop_rpm (a measurement of the shaft, not a demand);
// the vertical plane is driven, depending on what the log holds, by
//   Actuators:      the logged elevator (and tunnel thrusters) directly,
//   PitchCommands:  the logged pitch_cmd, tracked by the model's plane loop,
//   DepthCommands:  the logged depth_cmd, flown by the model's autopilot.
// Heading: the logged rudder if there is one, else heading hold on the logged
// heading_cmd (or heading). The model starts from the first row's depth,
// pitch, roll, heading and speed, with its autopilot integrators at zero.
// Driving channels are brought onto the model's time grid before the loop
// (linear for measurements, hold for commands; a gap holds the last value),
// a chunk of steps at a time, so memory follows the rows, not the time span;
// a grid time that coincides with a log row takes that row's value exactly.
// A gap between rows longer than 20 row spacings (at least 30 s) ends a span:
// the model restarts from the first row after it (logger drop-outs of days
// are not flown step by step).
#include <string>

#include "missionlog/mission_log.h"
#include "sim/depth_autopilot.h"
#include "sim/flown_mass.h"
#include "sim/sim_trace.h"
#include "sim/vehicle_model.h"
#include "sim/water_column.h"

namespace auv::sim {

enum class ReplayDrive { Auto, Actuators, PitchCommands, DepthCommands };

struct ReplayOptions {
  ReplayDrive drive = ReplayDrive::Auto;
  double dt_s = 0.05;  // model step; the log rows need not lie on its grid
  VehicleLoading loading;
  bool surface_model = false;
};

// What Auto picks for this log: Actuators if it has an elevator (and, for a
// vehicle with tunnel thrusters, thruster_front_rpm/thruster_aft_rpm), else
// PitchCommands if it has pitch_cmd, else DepthCommands if it has depth_cmd.
// Throws InputError naming the missing channel when the requested drive (or
// any drive, for Auto) is impossible.
ReplayDrive resolveReplayDrive(const VehicleModel& model, const MissionLog& recorded, ReplayDrive requested);
std::string replayDriveName(ReplayDrive drive);
ReplayDrive parseReplayDrive(const std::string& name);  // auto|actuators|pitch|depth, else InputError("drive")

// The trace has one sample per log row, at the model step nearest to the
// row's time (rows closer together than dt share a step and are sampled once).
SimTrace replay(const VehicleModel& model, const DepthAutopilotConfig& autopilot, const WaterColumn& water,
                const MissionLog& recorded, const ReplayOptions& options = {});

}  // namespace auv::sim
