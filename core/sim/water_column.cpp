#include "sim/water_column.h"

#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "seawater/seawater.h"

namespace auv::sim {

WaterColumn WaterColumn::uniform(double density_kgm3, double temperature_degC, double salinity_psu) {
  if (!(density_kgm3 > 900.0 && density_kgm3 < 1100.0)) {
    throw InputError("density_kgm3", "water density must be between 900 and 1100 kg/m^3",
                     "give the density of the water the vehicle flies in");
  }
  WaterColumn w;
  w.table_ = {{density_kgm3, temperature_degC, salinity_psu, 0.0}};
  w.uniform_dbar_per_m_ = units::paToDbar(density_kgm3 * units::g0);
  return w;
}

WaterColumn WaterColumn::fromCast(std::span<const CtdPoint> cast, double max_depth_m, double step_m,
                                  double latitude_deg) {
  if (cast.empty()) throw InputError("cast", "no CTD levels", "give at least one depth/T/S level");
  if (!(step_m > 0.0) || !(max_depth_m > 0.0)) {
    throw InputError("max_depth_m", "table depth and step must be positive", "use e.g. 1 m steps");
  }
  for (std::size_t i = 1; i < cast.size(); ++i) {
    if (!(cast[i].depth_m > cast[i - 1].depth_m)) {
      throw InputError("cast[" + std::to_string(i) + "].depth_m", "depths must increase strictly",
                       "sort the cast by depth and drop repeated levels");
    }
  }
  auto ts = [&](double z) {
    if (z <= cast.front().depth_m) return std::pair{cast.front().temperature_degC, cast.front().salinity_psu};
    if (z >= cast.back().depth_m) return std::pair{cast.back().temperature_degC, cast.back().salinity_psu};
    const auto it = std::upper_bound(cast.begin(), cast.end(), z,
                                     [](double d, const CtdPoint& c) { return d < c.depth_m; });
    const CtdPoint& b = *it;
    const CtdPoint& a = *(it - 1);
    const double f = (z - a.depth_m) / (b.depth_m - a.depth_m);
    return std::pair{a.temperature_degC + f * (b.temperature_degC - a.temperature_degC),
                     a.salinity_psu + f * (b.salinity_psu - a.salinity_psu)};
  };
  WaterColumn w;
  w.step_m_ = step_m;
  w.latitude_deg_ = latitude_deg;
  const auto n = static_cast<std::size_t>(std::ceil(max_depth_m / step_m)) + 1;
  w.table_.reserve(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    const double z = static_cast<double>(i) * step_m;
    const auto [t, s] = ts(z);
    const double p = seawater::pressureFromDepth(z, latitude_deg);
    w.table_.push_back({seawater::density(s, t, p), t, s, p});
  }
  return w;
}

}  // namespace auv::sim
