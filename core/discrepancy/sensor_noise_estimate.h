#pragma once
// The white sensor noise of a recording, per channel, for a noise twin of it
// (model_check.h): what a local polynomial cannot follow from row to row.
// The centre residual of a 7-row quartic fit (coefficients -5, 30, -75, 100,
// -75, 30, -5 over 231) passes no polynomial up to quintic and 0.658 of white
// noise; the median of its magnitude over the record, over 0.6745 x 0.658,
// is the noise sigma. Windows whose rows are not evenly spaced (within 10 %)
// or hold a missing value are skipped. A vehicle's motion at a 1 Hz row rate
// adds little: a 20 s pitch oscillation of 1 deg leaves 4e-5 deg, a 7 s one
// of 0.3 deg 0.003 deg (the 5-row quadratic's residual left 0.013 and 0.015).
#include "missionlog/mission_log.h"
#include "sim/sensor_noise.h"

namespace auv::discrepancy {

// Depth, pitch, roll, speed, heading, temperature, salinity and pressure, in
// the simulator's units (m, rad, m/s, degC, psu, dbar). A channel the log
// lacks, or with fewer than 20 usable windows, has zero noise. The rates the
// autopilot reads (depth rate, pitch rate) are not logged: zero.
sim::SensorNoise estimateSensorNoise(const MissionLog& log);

// One channel's sigma in its logged unit (0 when it cannot be measured).
double estimateChannelNoise(const MissionLog& log, const char* name);

}  // namespace auv::discrepancy
