#include "analysis/calibration_segments.h"

#include <cmath>

#include "analysis/auv_calibration.h"
#include "common/units.h"

namespace auv::analysis {
namespace {
enum { kSpeed = 0, kPitch, kRoll, kElev, kRate };

// An averaged leg's cycle products moved by what a shift of its means
// moves the products of its means (from a to b); the products of speed
// alone (au_u, au_u_e) do not move.
void moveCycleProducts(BalanceRegressors& r, const BalanceRegressors& a, const BalanceRegressors& b) {
  r.cc += b.cc - a.cc;
  r.sin_theta += b.sin_theta - a.sin_theta;
  r.au_w += b.au_w - a.au_w;
  r.u_w += b.u_w - a.u_w;
  r.aw_w += b.aw_w - a.aw_w;
}
}  // namespace

std::vector<CalibrationSegment> withPitchLowered(const std::vector<CalibrationSegment>& segs, double bias_rad) {
  std::vector<CalibrationSegment> out = segs;
  for (CalibrationSegment& s : out) {
    const std::array<double, 5> v0 = s.v;
    s.v[kPitch] -= bias_rad;
    if (!s.regressors) continue;
    const BalanceRegressors a = balanceRegressors({v0[kSpeed], v0[kPitch], v0[kRoll], v0[kElev], v0[kRate], s.density_kgm3});
    const BalanceRegressors b = balanceRegressors({s.v[kSpeed], s.v[kPitch], s.v[kRoll], s.v[kElev], s.v[kRate], s.density_kgm3});
    moveCycleProducts(*s.regressors, a, b);
  }
  return out;
}

SteadySegmentMeans withAttitudeRaised(SteadySegmentMeans s, double pitch_deg, double roll_deg) {
  if (pitch_deg == 0.0 && roll_deg == 0.0) return s;
  // As the calibration reads a segment (auv_trim_estimation.cpp, measOf).
  auto flight = [&](const SteadySegmentMeans& g) {
    return SteadyFlight{g.speed_mps.mean, units::degToRad(g.pitch_deg.mean),
                        g.roll_deg.valid() ? units::degToRad(g.roll_deg.mean) : 0.0,
                        std::isfinite(g.elevator_deg.mean) ? g.elevator_deg.mean : 0.0,
                        g.depth_rate_mps.valid() ? g.depth_rate_mps.mean : 0.0, g.density_kgm3};
  };
  const SteadySegmentMeans before = s;
  s.pitch_deg.mean += pitch_deg;
  if (s.roll_deg.valid()) s.roll_deg.mean += roll_deg;
  if (s.regressors) {
    const BalanceRegressors a = balanceRegressors(flight(before));
    const BalanceRegressors b = balanceRegressors(flight(s));
    moveCycleProducts(*s.regressors, a, b);
  }
  return s;
}

}  // namespace auv::analysis
