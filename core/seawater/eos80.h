#pragma once
// EOS-80: the International Equation of State of Seawater 1980 (Millero et al.
// 1980; Millero & Poisson 1981) in the form of UNESCO Tech. Pap. Mar. Sci. 44
// (Fofonoff & Millard 1983), eqs. 13-19:
//
//   rho(S,t,p) = rho(S,t,0) / (1 - p / K(S,t,p))
//
// S practical salinity (PSS-78), t temperature, p SEA pressure (absolute minus
// one standard atmosphere: 0 at the sea surface). The API takes p in dbar;
// the standard is written in bar (p_bar = p_dbar / 10) and K is in bar.
// Temperatures are ITS-90 unless TempScale::IPTS68 is passed.
// All inputs are range-checked (seawater/validation.h); out-of-range or NaN
// input throws auv::InputError.
#include "seawater/temperature_scale.h"

namespace auv::seawater {

// One-atmosphere density [kg/m^3]: standard mean ocean water (Bigg 1967)
// plus the Millero & Poisson (1981) salinity terms.
double densityAtSurface(double salinity_psu, double temperature_degC,
                        TempScale scale = TempScale::ITS90);

// Secant bulk modulus K(S,t,p) [bar] (not Pa, not dbar: the unit of the
// standard, so the published check values apply directly).
double secantBulkModulus(double salinity_psu, double temperature_degC, double pressure_dbar,
                         TempScale scale = TempScale::ITS90);

// In-situ density [kg/m^3] at sea pressure pressure_dbar.
double density(double salinity_psu, double temperature_degC, double pressure_dbar,
               TempScale scale = TempScale::ITS90);

}  // namespace auv::seawater
