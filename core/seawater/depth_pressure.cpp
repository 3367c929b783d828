#include "seawater/depth_pressure.h"

#include <cmath>
#include <numbers>

#include "seawater/eos80.h"
#include "seawater/validation.h"

namespace auv::seawater {
namespace {

constexpr double c1 = 9.72659, c2 = -2.2512e-5, c3 = 2.279e-10, c4 = -1.82e-15;
constexpr double kGravityGradient = 2.184e-6;  // gamma', m/s^2 per dbar

double sin2Lat(double latitude_deg) {
  const double s = std::sin(latitude_deg * std::numbers::pi / 180.0);
  return s * s;
}

// Gravity at the surface, International Formula 1967 as used in eq. 25.
double surfaceGravity(double x) { return 9.780318 * (1.0 + (5.2788e-3 + 2.36e-5 * x) * x); }

double depthUnchecked(double p, double g) {
  const double top = (((c4 * p + c3) * p + c2) * p + c1) * p;
  return top / (g + 0.5 * kGravityGradient * p);
}

double saundersUnchecked(double z, double x) {
  const double cc = 5.92e-3 + 5.25e-3 * x;
  return ((1.0 - cc) - std::sqrt((1.0 - cc) * (1.0 - cc) - 8.84e-6 * z)) / 4.42e-6;
}

}  // namespace

double depthFromPressure(double pressure_dbar, double latitude_deg) {
  requireInRange("pressure_dbar", pressure_dbar, kPressureRange);
  requireInRange("latitude_deg", latitude_deg, kLatitudeRange);
  return depthUnchecked(pressure_dbar, surfaceGravity(sin2Lat(latitude_deg)));
}

double pressureFromDepthSaunders(double depth_m, double latitude_deg) {
  requireInRange("depth_m", depth_m, kDepthRange);
  requireInRange("latitude_deg", latitude_deg, kLatitudeRange);
  return saundersUnchecked(depth_m, sin2Lat(latitude_deg));
}

double pressureFromDepth(double depth_m, double latitude_deg) {
  requireInRange("depth_m", depth_m, kDepthRange);
  requireInRange("latitude_deg", latitude_deg, kLatitudeRange);
  const double x = sin2Lat(latitude_deg);
  const double g = surfaceGravity(x);
  // Saunders is within 0.1 % of the root; eq. 25 is smooth and monotonic, so
  // two or three Newton steps reach machine precision.
  double p = saundersUnchecked(depth_m, x);
  for (int i = 0; i < 10; ++i) {
    const double den = g + 0.5 * kGravityGradient * p;
    const double top = (((c4 * p + c3) * p + c2) * p + c1) * p;
    const double dTop = ((4.0 * c4 * p + 3.0 * c3) * p + 2.0 * c2) * p + c1;
    const double f = top / den - depth_m;
    const double df = (dTop * den - top * 0.5 * kGravityGradient) / (den * den);
    const double dp = f / df;
    p -= dp;
    if (std::abs(dp) < 1e-10) break;
  }
  return p;
}

double densityAtDepth(double salinity_psu, double temperature_degC, double depth_m,
                      double latitude_deg, TempScale scale) {
  return density(salinity_psu, temperature_degC, pressureFromDepth(depth_m, latitude_deg), scale);
}

}  // namespace auv::seawater
