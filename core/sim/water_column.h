#pragma once
// The water the simulated vehicle flies through: density, temperature,
// salinity and pressure against depth. In-situ density comes from core
// seawater (EOS-80 with pressure) and is tabulated once on a depth grid, so
// the step loop does one linear interpolation instead of an equation of state.
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace auv::sim {

struct WaterSample {
  double density_kgm3 = 1000.0;
  double temperature_degC = 15.0;
  double salinity_psu = 0.0;
  double pressure_dbar = 0.0;
};

// One level of a CTD cast (or of a profile taken from a recorded log).
struct CtdPoint {
  double depth_m = 0.0;
  double temperature_degC = 10.0;
  double salinity_psu = 35.0;
};

class WaterColumn {
 public:
  // Constant density, e.g. a towing tank; hydrostatic pressure rho g z.
  static WaterColumn uniform(double density_kgm3, double temperature_degC = 15.0, double salinity_psu = 0.0);
  // Temperature and salinity interpolated linearly between the cast levels
  // (held constant above the first and below the last), EOS-80 density with
  // UNESCO pressure, tabulated every step_m down to max_depth_m.
  static WaterColumn fromCast(std::span<const CtdPoint> cast, double max_depth_m, double step_m = 1.0,
                              double latitude_deg = 45.0);

  // Internal wave: the stratification moves up and down by
  // amplitude sin(2 pi t / period + phase), so at a fixed depth the density,
  // temperature and salinity oscillate (pressure does not). Zero amplitude = none.
  void setInternalWave(double amplitude_m, double period_s, double phase_rad = 0.0) {
    wave_amplitude_m_ = amplitude_m;
    wave_omega_ = period_s > 0.0 ? 2.0 * 3.14159265358979323846 / period_s : 0.0;
    wave_phase_ = phase_rad;
  }
  // The latitude the cast's pressure was computed for (UNESCO gravity): a log
  // flown in it says so, or its depth and pressure disagree by up to 0.5 %.
  double latitudeDeg() const { return latitude_deg_; }
  bool hasInternalWave() const { return wave_amplitude_m_ != 0.0 && wave_omega_ > 0.0; }
  // The water at a depth at time t (s) of the run.
  WaterSample at(double depth_m, double t_s) const {
    if (!hasInternalWave()) return at(depth_m);
    const double eta = wave_amplitude_m_ * std::sin(wave_omega_ * t_s + wave_phase_);
    WaterSample s = at(std::max(0.0, depth_m - eta));
    s.pressure_dbar = at(depth_m).pressure_dbar;
    return s;
  }

  WaterSample at(double depth_m) const {
    if (table_.size() == 1) {
      WaterSample s = table_[0];
      s.pressure_dbar = depth_m > 0.0 ? uniform_dbar_per_m_ * depth_m : 0.0;
      return s;
    }
    const double x = depth_m / step_m_;
    if (x <= 0.0) return table_.front();
    const std::size_t last = table_.size() - 1;
    std::size_t i = static_cast<std::size_t>(x);
    if (i >= last) i = last - 1;
    const double f = x - static_cast<double>(i);  // > 1 extrapolates below the table
    const WaterSample& a = table_[i];
    const WaterSample& b = table_[i + 1];
    return {a.density_kgm3 + f * (b.density_kgm3 - a.density_kgm3),
            a.temperature_degC + f * (b.temperature_degC - a.temperature_degC),
            a.salinity_psu + f * (b.salinity_psu - a.salinity_psu),
            a.pressure_dbar + f * (b.pressure_dbar - a.pressure_dbar)};
  }

 private:
  std::vector<WaterSample> table_;
  double step_m_ = 1.0;
  double latitude_deg_ = 45.0;
  double uniform_dbar_per_m_ = 0.0;
  double wave_amplitude_m_ = 0.0, wave_omega_ = 0.0, wave_phase_ = 0.0;
};

}  // namespace auv::sim
