#pragma once
// Gaussian sensor noise that is identical for a given seed on every platform:
// std::mt19937_64's output is fixed by the standard, but
// std::normal_distribution is not, so the Box-Muller transform is done here.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace auv::sim {

// Standard deviations; zero switches a channel's noise off.
struct SensorNoise {
  double depth_m = 0.0;
  double depth_rate_mps = 0.0;
  double pitch_rad = 0.0;
  double pitch_rate_radps = 0.0;
  double roll_rad = 0.0;
  double speed_mps = 0.0;
  // Logged only (the autopilot does not use them except heading).
  double heading_rad = 0.0;
  double temperature_degC = 0.0;
  double salinity_psu = 0.0;
  double pressure_dbar = 0.0;
};

class GaussianSource {
 public:
  explicit GaussianSource(std::uint64_t seed) : rng_(seed) {}

  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    // 53-bit uniforms in (0, 1]; u1 > 0 keeps the log finite.
    const double u1 = (static_cast<double>(rng_() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(rng_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2.0 * std::numbers::pi * u2);
    has_spare_ = true;
    return r * std::cos(2.0 * std::numbers::pi * u2);
  }
  double next(double sigma) { return sigma > 0.0 ? sigma * next() : 0.0; }

 private:
  std::mt19937_64 rng_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace auv::sim
