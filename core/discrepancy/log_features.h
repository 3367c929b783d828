#pragma once
// Small readers shared by the glider and AUV check models: channels at a set
// of times, and the time since the last actuator or command change (one of
// the factors the localisation breaks residuals down by).
#include <initializer_list>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "missionlog/mission_log.h"

namespace auv::discrepancy {

bool hasChannel(const MissionLog& log, const char* name, std::size_t min_samples = 2);

// Channel values at ascending times: linear between samples (hold = last
// sample for commands); NaN outside the record or across gaps > max_gap_s.
// Empty when the channel is missing.
std::vector<double> channelAt(const MissionLog& log, const char* name, std::span<const double> times, bool hold,
                              double max_gap_s);

// Seconds since any of the listed channels last changed by more than its
// threshold (channel, threshold in the channel's unit), at ascending times.
// NaN before the first change.
std::vector<double> sinceLastChange(const MissionLog& log,
                                    std::initializer_list<std::pair<const char*, double>> channels,
                                    std::span<const double> times);

}  // namespace auv::discrepancy
