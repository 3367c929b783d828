#include "sim/water_from_log.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "common/input_error.h"
#include "missionlog/resample.h"

namespace auv::sim {

WaterColumn waterColumnFromLog(const MissionLog& log, double bin_m, double latitude_deg, double margin_m) {
  if (!(bin_m > 0.0)) throw InputError("bin_m", "must be positive", "use e.g. 1 m bins");
  const TimeSeries depth = log.series("depth");  // InputError names a missing channel
  const TimeSeries T = alignTo(log, "temperature", "depth");
  const TimeSeries S = alignTo(log, "salinity", "depth");
  struct Bin {
    double z = 0.0, t = 0.0, s = 0.0;
    int n = 0;
  };
  std::map<long, Bin> bins;
  double deepest = 0.0;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    if (std::isnan(T.v[i]) || std::isnan(S.v[i]) || std::isnan(depth.v[i])) continue;
    const double z = std::max(0.0, depth.v[i]);
    Bin& b = bins[std::lround(std::floor(z / bin_m))];
    b.z += z;
    b.t += T.v[i];
    b.s += S.v[i];
    ++b.n;
    deepest = std::max(deepest, z);
  }
  if (bins.empty()) {
    throw InputError("temperature", "the log has no row with depth, temperature and salinity together",
                     "give the water separately (--env FILE) or use a log with CTD channels");
  }
  std::vector<CtdPoint> cast;
  for (const auto& [index, b] : bins) {
    const double n = static_cast<double>(b.n);
    cast.push_back({b.z / n, b.t / n, b.s / n});
  }
  // Mean depths of consecutive bins increase, but two bins can meet at a
  // boundary to rounding: keep the cast strictly increasing.
  std::vector<CtdPoint> strict;
  for (const CtdPoint& c : cast) {
    if (strict.empty() || c.depth_m > strict.back().depth_m) strict.push_back(c);
  }
  return WaterColumn::fromCast(strict, deepest + margin_m, bin_m, latitude_deg);
}

}  // namespace auv::sim
