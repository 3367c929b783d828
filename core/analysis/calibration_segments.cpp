#include "analysis/calibration_segments.h"

#include <cmath>

#include "analysis/auv_calibration.h"

namespace auv::analysis {
namespace {
enum { kSpeed = 0, kPitch, kRoll, kElev, kRate };
}  // namespace

std::vector<CalibrationSegment> withPitchLowered(const std::vector<CalibrationSegment>& segs, double bias_rad) {
  std::vector<CalibrationSegment> out = segs;
  for (CalibrationSegment& s : out) {
    const std::array<double, 5> v0 = s.v;
    s.v[kPitch] -= bias_rad;
    if (!s.regressors) continue;
    const BalanceRegressors a = balanceRegressors({v0[kSpeed], v0[kPitch], v0[kRoll], v0[kElev], v0[kRate], s.density_kgm3});
    const BalanceRegressors b = balanceRegressors({s.v[kSpeed], s.v[kPitch], s.v[kRoll], s.v[kElev], s.v[kRate], s.density_kgm3});
    BalanceRegressors& r = *s.regressors;
    r.cc += b.cc - a.cc;
    r.sin_theta += b.sin_theta - a.sin_theta;
    r.au_w += b.au_w - a.au_w;
    r.u_w += b.u_w - a.u_w;
    r.aw_w += b.aw_w - a.aw_w;
  }
  return out;
}

}  // namespace auv::analysis
