#pragma once
// The state a replay of a log starts (or restarts) from: shared by the
// simulator's replay (sim::replay) and the model check's (termReplay), so
// both fly the same vehicle from the same logged row.
#include "missionlog/mission_log.h"
#include "sim/step_engine.h"
#include "sim/vehicle_model.h"

namespace auv::sim {

// Value of `name` at t0; if the log has none there, its first sample after t0
// (a span may start on a row where that sensor dropped out); `fallback`
// without any sample.
double loggedValueAt(const MissionLog& log, const char* name, double t0, double fallback);

// Least-squares slope of the logged depth over [t0, t0 + window_s] [m/s, down
// positive]; empty without three finite samples.
std::optional<double> loggedDepthRate(const MissionLog& log, double t0, double window_s = 5.0);

// The logged depth, attitude, heading, speed and propeller at t0. With
// `in_motion` (a restart after a drop-out, a surface interval or a short
// horizon) also the depth rate, the stern plane and the tunnel thrusters: a
// restart mid-dive started at rest lags the glide by its first seconds'
// travel and keeps that as a depth offset. A log's first row starts at rest
// in heave, as the simulated mission it may be the record of did.
InitialState replayStartState(const MissionLog& log, double t0, const VehicleModel& model, bool in_motion);

}  // namespace auv::sim
