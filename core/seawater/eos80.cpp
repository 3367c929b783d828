#include "seawater/eos80.h"

#include <cmath>

#include "seawater/validation.h"

// Coefficient names follow UNESCO Tech. Paper 44 (eqs. 13-19) so the code can
// be checked against the paper line by line. t is IPTS-68, p is in bar.
namespace auv::seawater {
namespace {

void validate(double s, double t, double p_dbar) {
  requireInRange("salinity_psu", s, kSalinityRange);
  requireInRange("temperature_degC", t, kTemperatureRange);
  requireInRange("pressure_dbar", p_dbar, kPressureRange);
}

// Eq. 14: density of standard mean ocean water (Bigg 1967).
double smow(double t) {
  return 999.842594 +
         t * (6.793952e-2 + t * (-9.095290e-3 + t * (1.001685e-4 + t * (-1.120083e-6 + t * 6.536332e-9))));
}

// Eq. 13: one-atmosphere density.
double rho0(double s, double t) {
  const double a = 8.24493e-1 + t * (-4.0899e-3 + t * (7.6438e-5 + t * (-8.2467e-7 + t * 5.3875e-9)));
  const double b = -5.72466e-3 + t * (1.0227e-4 + t * -1.6546e-6);
  constexpr double c = 4.8314e-4;
  return smow(t) + (a + b * std::sqrt(s) + c * s) * s;
}

// Eqs. 15-19: secant bulk modulus, p in bar.
double kBar(double s, double t, double p) {
  const double sr = std::sqrt(s);
  const double kw = 19652.21 + t * (148.4206 + t * (-2.327105 + t * (1.360477e-2 + t * -5.155288e-5)));
  const double aw = 3.239908 + t * (1.43713e-3 + t * (1.16092e-4 + t * -5.77905e-7));
  const double bw = 8.50935e-5 + t * (-6.12293e-6 + t * 5.2787e-8);
  const double k0 = kw + s * (54.6746 + t * (-0.603459 + t * (1.09987e-2 + t * -6.1670e-5)) +
                              sr * (7.944e-2 + t * (1.6483e-2 + t * -5.3009e-4)));
  const double a = aw + s * (2.2838e-3 + t * (-1.0981e-5 + t * -1.6078e-6) + sr * 1.91075e-4);
  const double b = bw + s * (-9.9348e-7 + t * (2.0816e-8 + t * 9.1697e-10));
  return k0 + p * (a + p * b);
}

}  // namespace

double densityAtSurface(double salinity_psu, double temperature_degC, TempScale scale) {
  validate(salinity_psu, temperature_degC, 0.0);
  return rho0(salinity_psu, toT68(temperature_degC, scale));
}

double secantBulkModulus(double salinity_psu, double temperature_degC, double pressure_dbar,
                         TempScale scale) {
  validate(salinity_psu, temperature_degC, pressure_dbar);
  return kBar(salinity_psu, toT68(temperature_degC, scale), pressure_dbar / 10.0);
}

double density(double salinity_psu, double temperature_degC, double pressure_dbar, TempScale scale) {
  validate(salinity_psu, temperature_degC, pressure_dbar);
  const double t68 = toT68(temperature_degC, scale);
  const double p_bar = pressure_dbar / 10.0;
  return rho0(salinity_psu, t68) / (1.0 - p_bar / kBar(salinity_psu, t68, p_bar));
}

}  // namespace auv::seawater
