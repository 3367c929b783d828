#pragma once
// Statistics of the model check's residual arrays (row-major, one column per
// channel, NaN where not available): robust noise level, effective sample
// share, per-channel sums of squares. Internal to the model check.
#include <limits>
#include <vector>

#include "discrepancy/check_model.h"
#include "discrepancy/weighted_fit.h"

namespace auv::discrepancy::detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Smallest RMS a channel is scored against, so that a channel the base model
// already matches cannot dominate the relative simulation cost.
double channelFloor(Channel c);

// Per equation channel: MAD-based sigma, never below channelFloor.
std::vector<double> robustSigmas(const FitSetup& s, const std::vector<double>& r);

// Effective / actual sample size per channel from the lag-1
// autocorrelation of the residuals within blocks (AR(1): (1 - r) / (1 + r)).
std::vector<double> effectiveShares(const FitSetup& s, const SampleTable& S, const std::vector<double>& r);

double rmsOf(double sse, double n);  // NaN when n is 0

std::vector<double> channelColumn(const std::vector<double>& v, std::size_t C, std::size_t c);

// Sum of squares and count of the finite values of each of the C channels.
void rmsPerChannel(const std::vector<double>& v, std::size_t C, std::vector<double>& sse, std::vector<double>& n);

}  // namespace auv::discrepancy::detail
