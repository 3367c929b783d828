#pragma once
// One calibrated vehicle constant as the analysis reports it (JSON
// `calibration` list: id, value, unit, sigma, profile_value, identified).
#include <string>

namespace auv::analysis {

struct CalibrationParameter {
  std::string id, unit;
  double value = 0.0, sigma = 0.0;
  double prior_value = 0.0, prior_sigma = 0.0;
  double profile_value = 0.0;
  bool identified = false;  // the log narrowed it: posterior sigma below half the prior sigma
  // false: reported for what the log says, but the estimate held the
  // profile's value (the hull law when its change was not significant).
  bool used = true;
};

}  // namespace auv::analysis
