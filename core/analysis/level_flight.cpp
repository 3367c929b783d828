#include "analysis/level_flight.h"

#include <cmath>

#include "common/units.h"

namespace auv::analysis {

namespace {

// For a given pitch the heave balance fixes the elevator (it is linear in
// it); what is left of the pitch balance is a scalar function of pitch.
struct Balance {
  const SteadyHydroCoefficients& c;
  const LevelFlightInput& in;

  double elevatorFor(double theta) const {
    const double u = in.speed_mps;
    const SteadyFlight f{u, theta, in.roll_rad, 0.0, in.depth_rate_mps, in.density_kgm3};
    const HydroLoads h = steadyHydroLoads(c, f);
    const double cc = std::cos(theta) * std::cos(in.roll_rad);
    return ((in.buoyancy_n - in.weight_n) * cc - h.Z()) / (c.Z_e_per_deg * std::abs(u) * u);
  }
  double momentResidual(double theta) const {
    const SteadyFlight f{in.speed_mps, theta, in.roll_rad, elevatorFor(theta), in.depth_rate_mps, in.density_kgm3};
    const HydroLoads h = steadyHydroLoads(c, f);
    const double cc = std::cos(theta) * std::cos(in.roll_rad);
    return in.weight_n * (in.bg_m * std::sin(theta) + in.x_g_m * cc) - h.M();
  }
};

}  // namespace

LevelFlight solveLevelFlight(const SteadyHydroCoefficients& c, const LevelFlightInput& in) {
  LevelFlight out;
  if (!c.has_planes || c.Z_e_per_deg == 0.0 || !(std::abs(in.speed_mps) > 0.05)) return out;
  const Balance b{c, in};
  // Bracket the root on a 0.5 deg grid outward from level, so the trim
  // nearest to level is found first.
  const double step = units::degToRad(0.5), limit = units::degToRad(30.0);
  double lo = 0.0, flo = b.momentResidual(0.0), hi = 0.0;
  bool bracketed = flo == 0.0;
  for (double d = step; !bracketed && d <= limit + 1e-12; d += step) {
    for (double s : {1.0, -1.0}) {
      const double a = s * (d - step), t = s * d;
      const double fa = b.momentResidual(a), ft = b.momentResidual(t);
      if (fa == 0.0 || (fa < 0.0) != (ft < 0.0)) {
        lo = a, flo = fa, hi = t;
        bracketed = true;
        break;
      }
    }
  }
  if (!bracketed) return out;
  // Bisection to 1e-9 rad: cheap, and it never leaves the bracket.
  for (int i = 0; i < 60 && std::abs(hi - lo) > 1e-9 && flo != 0.0; ++i) {
    const double m = 0.5 * (lo + hi), fm = b.momentResidual(m);
    if ((fm < 0.0) == (flo < 0.0)) {
      lo = m, flo = fm;
    } else {
      hi = m;
    }
  }
  out.ok = true;
  out.pitch_rad = flo == 0.0 ? lo : 0.5 * (lo + hi);
  out.elevator_deg = b.elevatorFor(out.pitch_rad);
  return out;
}

}  // namespace auv::analysis
