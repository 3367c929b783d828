#pragma once
// Where a residual concentrates: broken down by time, mission phase, pressure
// band, temperature band, speed band, rpm band, pitch band and time since the
// last actuator change; factors ranked by the share of the residual's
// variance their bins explain (eta squared), and the top ones described in
// words a technician can act on ("vertical-velocity error grows 0.9 cm/s per
// 100 dbar below 150 dbar; independent of speed").
#include <span>
#include <string>
#include <vector>

#include "common/message.h"
#include "discrepancy/check_model.h"

namespace auv::discrepancy {

struct BinSummary {
  std::string label;
  double mean = 0.0;  // display unit
  double rms = 0.0;
  std::size_t count = 0;
};

struct FactorFinding {
  std::string factor;   // "pressure", "phase", ...
  double share = 0.0;   // eta^2: between-bin variance / total variance
  bool linear = false;  // described as a trend
  double slope = 0.0;   // display unit per factor step
  std::string step;     // "100 dbar"
  Message text;  // English, with its id and arguments (check_messages.h)
  std::vector<BinSummary> bins;
};

struct Localisation {
  Channel channel = Channel::kVerticalVelocity;
  std::string source;  // "equation error" or "simulation error"
  double rms = 0.0;    // display unit
  double mean = 0.0;
  std::size_t count = 0;
  std::vector<FactorFinding> ranked;  // largest share first
  Message summary;                   // top finding in words (id check.summary)
};

// `value` per sample row (SI, NaN = not available).
Localisation localise(const SampleTable& s, std::span<const double> value, Channel channel, const std::string& source);

}  // namespace auv::discrepancy
