#include "missionlog/detail/attitude_sanity.h"

#include <cmath>

namespace auv::detail {

AttitudeCheck checkAttitudeDeg(std::string_view base, std::vector<double>& deg) {
  AttitudeCheck c;
  if (base == "pitch") c.limit_deg = 90.5;
  else if (base == "roll") c.limit_deg = 180.5;
  else return c;
  for (std::size_t i = 0; i < deg.size(); ++i) {
    double& v = deg[i];
    if (!std::isfinite(v)) continue;
    ++c.valid;
    const double a = std::fabs(v);
    if (a > c.limit_deg) {
      if (!c.beyond) c.first_beyond = i;
      ++c.beyond;
      c.worst_deg = std::max(c.worst_deg, a);
      v = std::nan("");
    } else {
      c.max_abs_deg = std::max(c.max_abs_deg, a);
    }
  }
  return c;
}

bool looksLikeRadians(std::string_view base, const AttitudeCheck& c, double depth_span_m) {
  if (c.limit_deg == 0.0 || c.beyond > 0 || c.valid < 10 || !(c.max_abs_deg > 0.0)) return false;
  const double small = base == "pitch" ? 1.6 : 3.2;
  return c.max_abs_deg <= small && depth_span_m > 5.0;
}

}  // namespace auv::detail
