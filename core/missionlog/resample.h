#pragma once
// Bringing channels onto a common time base on demand. Interpolation never
// bridges a hole longer than `max_gap_s` and never extrapolates: where the
// source cannot say what the value was, the result is NaN (not sampled), so a
// sensor drop-out cannot turn into a straight line that looks like data.
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "missionlog/mission_log.h"

namespace auv {

enum class Interpolation {
  kLinear,  // measured quantities
  kHold,    // commands and set points: a value holds until the next one is written
};

struct ResampleOptions {
  Interpolation method = Interpolation::kLinear;
  // Linear: NaN where the two samples around a target are further apart.
  // Hold: NaN where the last sample is older than this.
  double max_gap_s = std::numeric_limits<double>::infinity();
};

// Values of `source` at times `at` (any order). Targets that coincide with a
// source sample get that sample exactly.
std::vector<double> resample(const TimeSeries& source, std::span<const double> at,
                             const ResampleOptions& options = {});

// t0, t0 + dt, ... up to t1 (inclusive within 1e-9 dt); computed as t0 + k dt
// so the grid does not drift. Throws std::invalid_argument for dt <= 0 or
// non-finite bounds.
std::vector<double> uniformGrid(double t0, double t1, double dt);

// Channel `name` evaluated at the valid-sample times of channel `onto`.
TimeSeries alignTo(const MissionLog& log, std::string_view name, std::string_view onto,
                   const ResampleOptions& options = {});

// Channel `name` on a uniform grid spanning its own valid samples.
TimeSeries resampleUniform(const MissionLog& log, std::string_view name, double dt,
                           const ResampleOptions& options = {});

}  // namespace auv
