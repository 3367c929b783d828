// The profile's steady coefficients with the calibrated groups
// (auv_calibration.h: pitchMomentUw, calibratedCoefficients).
#include "analysis/auv_calibration.h"

namespace auv::analysis {

double pitchMomentUw(const SteadyHydroCoefficients& c, double rho, double munk_factor) {
  const double L = c.reference_length_m;
  return 0.5 * rho * L * L * L * c.Mw_prime + munk_factor * (c.Xudot_kg - c.Zwdot_kg);
}

SteadyHydroCoefficients calibratedCoefficients(const SteadyHydroCoefficients& c, double rho_ref,
                                               const Eigen::VectorXd& p) {
  SteadyHydroCoefficients k = c;
  const double L = c.reference_length_m;
  k.Zw_prime *= p(kHeave);
  k.Zww_kg_per_m *= p(kCrossflow);
  k.Mww_kg *= p(kCrossflow);
  // The whole linear pitch moment as M_w' with the Munk moment inside it.
  k.munk_factor = 0.0;
  k.Mw_prime = p(kPitchUw) / (0.5 * rho_ref * L * L * L);
  k.munk_stated = true;
  if (c.has_planes) {
    k.Z_e_per_deg *= p(kPlanes);
    k.M_e_per_deg *= p(kPlanes);
  }
  return k;
}

}  // namespace auv::analysis
