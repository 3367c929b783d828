#include "discrepancy/sensor_noise_estimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "common/units.h"

namespace auv::discrepancy {

double estimateChannelNoise(const MissionLog& log, const char* name) {
  const LogChannel* c = log.find(name);
  if (c == nullptr) return 0.0;
  const std::vector<double>& x = c->values;
  const std::vector<double>& t = log.time;
  constexpr std::size_t W = 7;
  constexpr std::array<double, W> kResidual = {-5.0 / 231, 30.0 / 231, -75.0 / 231, 100.0 / 231,
                                               -75.0 / 231, 30.0 / 231, -5.0 / 231};
  constexpr double kWhiteGain = 0.657952;  // sqrt(23100) / 231
  std::vector<double> r;
  r.reserve(x.size());
  for (std::size_t i = W / 2; i + W / 2 < x.size(); ++i) {
    const double h = t[i] - t[i - 1];
    bool ok = h > 0.0;
    double v = 0.0;
    for (std::size_t j = 0; ok && j < W; ++j) {
      const std::size_t k = i - W / 2 + j;
      ok = std::isfinite(x[k]) && (j == 0 || std::abs((t[k] - t[k - 1]) - h) <= 0.1 * h);
      v += kResidual[j] * x[k];
    }
    if (ok) r.push_back(std::abs(v));
  }
  if (r.size() < 20) return 0.0;
  auto mid = r.begin() + static_cast<long>(r.size() / 2);
  std::nth_element(r.begin(), mid, r.end());
  return *mid / (0.67449 * kWhiteGain);
}

sim::SensorNoise estimateSensorNoise(const MissionLog& log) {
  sim::SensorNoise n;
  const double deg = units::degToRad(1.0);
  n.depth_m = estimateChannelNoise(log, "depth");
  n.pitch_rad = estimateChannelNoise(log, "pitch") * deg;
  n.roll_rad = estimateChannelNoise(log, "roll") * deg;
  n.speed_mps = estimateChannelNoise(log, "speed");
  n.heading_rad = estimateChannelNoise(log, "heading") * deg;
  n.temperature_degC = estimateChannelNoise(log, "temperature");
  n.salinity_psu = estimateChannelNoise(log, "salinity");
  n.pressure_dbar = estimateChannelNoise(log, "pressure");
  return n;
}

}  // namespace auv::discrepancy
