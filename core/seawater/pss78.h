#pragma once
// PSS-78, the Practical Salinity Scale 1978 (Lewis & Perkin 1981), in the form
// of UNESCO Tech. Pap. Mar. Sci. 44 (Fofonoff & Millard 1983), eqs. 1-4:
//
//   R  = C(S,t,p) / C(35,15,0)        conductivity ratio
//   R  = Rp * rt * Rt                 pressure, temperature, salinity factors
//   S  = sum a_i Rt^(i/2) + dS(t,Rt)
//
// C(35,15,0) = 4.2914 S/m (42.914 mS/cm), defined at 15 degC IPTS-68.
// Temperatures are ITS-90 unless TempScale::IPTS68 is passed; pressures are
// sea pressure in dbar. PSS-78 is defined for 2 <= S <= 42; below S = 2 the
// forward functions still return the formula's value (an extrapolation).
#include "seawater/temperature_scale.h"

namespace auv::seawater {

inline constexpr double kConductivity35_15_0_Sm = 4.2914;

// Practical salinity [psu] from the ratio R = C / C(35,15,0).
double salinityFromConductivityRatio(double conductivity_ratio, double temperature_degC,
                                     double pressure_dbar, TempScale scale = TempScale::ITS90);

// Practical salinity [psu] from in-situ conductivity [S/m].
double salinityFromConductivity(double conductivity_Sm, double temperature_degC,
                                double pressure_dbar, TempScale scale = TempScale::ITS90);

// Inverse of salinityFromConductivityRatio: Newton iteration on sqrt(Rt),
// then the closed-form quadratic for Rp (as in UNESCO's CNDR). 2 <= S <= 42.
double conductivityRatioFromSalinity(double salinity_psu, double temperature_degC,
                                     double pressure_dbar, TempScale scale = TempScale::ITS90);

// In-situ conductivity [S/m] for a practical salinity, 2 <= S <= 42.
double conductivityFromSalinity(double salinity_psu, double temperature_degC, double pressure_dbar,
                                TempScale scale = TempScale::ITS90);

}  // namespace auv::seawater
