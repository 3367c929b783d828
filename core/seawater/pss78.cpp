#include "seawater/pss78.h"

#include <cmath>

#include "seawater/validation.h"

// Coefficient names follow UNESCO Tech. Paper 44 (eqs. 1-4); t is IPTS-68.
namespace auv::seawater {
namespace {

constexpr double a[6] = {0.0080, -0.1692, 25.3851, 14.0941, -7.0261, 2.7081};
constexpr double b[6] = {0.0005, -0.0056, -0.0066, -0.0375, 0.0636, -0.0144};
constexpr double kK = 0.0162;

// Eq. 3: rt(t) = C(35,t,0) / C(35,15,0).
double rt(double t) {
  return 0.6766097 + t * (2.00564e-2 + t * (1.104259e-4 + t * (-6.9698e-7 + t * 1.0031e-9)));
}

// Pieces of eq. 4, Rp = 1 + pTerm / (tTerm + rCoef * R).
double pTerm(double p) { return p * (2.070e-5 + p * (-6.370e-10 + p * 3.989e-15)); }
double tTerm(double t) { return 1.0 + t * (3.426e-2 + t * 4.464e-4); }
double rCoef(double t) { return 4.215e-1 - 3.107e-3 * t; }

// Eqs. 1-2 written in x = sqrt(Rt): S(x) = sum a_i x^i + f(t) sum b_i x^i.
double salinityOfX(double x, double t) {
  const double f = (t - 15.0) / (1.0 + kK * (t - 15.0));
  double sa = 0.0, sb = 0.0;
  for (int i = 5; i >= 0; --i) {
    sa = sa * x + a[i];
    sb = sb * x + b[i];
  }
  return sa + f * sb;
}

double dSalinityDx(double x, double t) {
  const double f = (t - 15.0) / (1.0 + kK * (t - 15.0));
  double da = 0.0, db = 0.0;
  for (int i = 5; i >= 1; --i) {
    da = da * x + i * a[i];
    db = db * x + i * b[i];
  }
  return da + f * db;
}

void validateTp(double t, double p_dbar) {
  requireInRange("temperature_degC", t, kTemperatureRange);
  requireInRange("pressure_dbar", p_dbar, kPressureRange);
}

double salinityFromRatioUnchecked(double r, double t68, double p) {
  const double rp = 1.0 + pTerm(p) / (tTerm(t68) + rCoef(t68) * r);
  const double rtt = r / (rp * rt(t68));
  return salinityOfX(std::sqrt(rtt), t68);
}

}  // namespace

double salinityFromConductivityRatio(double conductivity_ratio, double temperature_degC,
                                     double pressure_dbar, TempScale scale) {
  requireInRange("conductivity_ratio", conductivity_ratio, kConductivityRatioRange);
  validateTp(temperature_degC, pressure_dbar);
  return salinityFromRatioUnchecked(conductivity_ratio, toT68(temperature_degC, scale),
                                    pressure_dbar);
}

double salinityFromConductivity(double conductivity_Sm, double temperature_degC,
                                double pressure_dbar, TempScale scale) {
  requireInRange("conductivity_Sm", conductivity_Sm, kConductivityRange);
  validateTp(temperature_degC, pressure_dbar);
  return salinityFromRatioUnchecked(conductivity_Sm / kConductivity35_15_0_Sm,
                                    toT68(temperature_degC, scale), pressure_dbar);
}

double conductivityRatioFromSalinity(double salinity_psu, double temperature_degC,
                                     double pressure_dbar, TempScale scale) {
  requireInRange("salinity_psu", salinity_psu, kPracticalSalinityRange);
  validateTp(temperature_degC, pressure_dbar);
  const double t = toT68(temperature_degC, scale);

  // S(x) is monotonic for S >= 2, and sqrt(S/35) is within a few per cent of
  // the root, so Newton converges quadratically in 3-5 steps.
  double x = std::sqrt(salinity_psu / 35.0);
  for (int i = 0; i < 30; ++i) {
    const double dx = (salinityOfX(x, t) - salinity_psu) / dSalinityDx(x, t);
    x -= dx;
    if (std::abs(dx) < 1e-15) break;
  }

  // R = u * Rp(R) with u = Rt * rt is a quadratic in R:
  //   c R^2 + (B - u c) R - u (A + B) = 0,  A = pTerm, B = tTerm, c = rCoef.
  // The roots have opposite signs; take the positive one in the form that
  // does not cancel.
  const double u = x * x * rt(t);
  const double qa = rCoef(t);
  const double qb = tTerm(t) - u * qa;
  const double qc = -u * (pTerm(pressure_dbar) + tTerm(t));
  const double sqrtDisc = std::sqrt(qb * qb - 4.0 * qa * qc);
  return qb >= 0.0 ? 2.0 * qc / -(qb + sqrtDisc) : (sqrtDisc - qb) / (2.0 * qa);
}

double conductivityFromSalinity(double salinity_psu, double temperature_degC, double pressure_dbar,
                                TempScale scale) {
  return kConductivity35_15_0_Sm *
         conductivityRatioFromSalinity(salinity_psu, temperature_degC, pressure_dbar, scale);
}

}  // namespace auv::seawater
