#pragma once
// Recording against simulation for people to look at: for every simulation
// channel of a model check, the recorded trace at the compared samples and
// the model's replay with the ballast state alone ("before") and with the
// accepted terms ("after"). The simulated traces are recorded - simulation
// error, so the gap a chart shows is exactly the error the check scored;
// the recorded trace comes from the log (depth, or pressure converted;
// pitch, roll, speed; vertical velocity as minus the depth rate).
#include <string>
#include <vector>

#include "discrepancy/check_model.h"
#include "discrepancy/model_check.h"
#include "missionlog/mission_log.h"

namespace auv::discrepancy {

struct ChannelOverlay {
  Channel channel = Channel::kDepth;
  std::string unit;  // display unit (channelUnit)
  // One value per SampleTable row, display unit; NaN where not scored.
  std::vector<double> recorded, simulated_before, simulated_after;
  double rms_before = 0.0, rms_after = 0.0;  // of recorded - simulated over the scored rows
  double recorded_sd = 0.0;                  // spread of the recorded trace over the same rows
  // rms_before / recorded_sd: how badly the ballast-only model misses, in
  // units of the channel's own variation, so channels of different units compare.
  double mismatch = 0.0;
  std::size_t scored = 0;
};

struct SimulationOverlay {
  std::vector<double> t_s;  // the SampleTable's times
  std::vector<ChannelOverlay> channels;  // in simulationChannels() order
  std::size_t largest = 0;  // index of the largest mismatch (0 when there are none)
};

// Two whole-log replays (result.base_params and result.final_params).
// `log` must be the recording the model was built from.
SimulationOverlay simulationOverlay(const CheckModel& model, const ModelCheckResult& result, const MissionLog& log);

}  // namespace auv::discrepancy
