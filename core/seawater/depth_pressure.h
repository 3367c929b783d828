#pragma once
// Depth <-> sea pressure (UNESCO Tech. Pap. Mar. Sci. 44, Fofonoff & Millard
// 1983, eq. 25; Saunders & Fofonoff 1976): the hydrostatic integral of a
// standard ocean (S = 35, t = 0 degC) with latitude-dependent gravity
// (International Formula 1967) and a mean vertical gravity gradient.
// Depth in metres positive down, pressure in dbar (0 at the sea surface).
// See docs/decisions/seawater-depth-pressure.md.
#include "seawater/temperature_scale.h"

namespace auv::seawater {

// Used whenever the latitude of the dive is not known. Gravity differs by
// 0.53 % between equator and pole; 45 deg keeps the depth error within
// +-0.27 % anywhere (UNESCO table: 9699.84 m at 10000 dbar vs 9725.47 / 9674.23).
inline constexpr double kDefaultLatitude_deg = 45.0;

// UNESCO 1983 eq. 25, depth [m] from sea pressure [dbar].
double depthFromPressure(double pressure_dbar, double latitude_deg = kDefaultLatitude_deg);

// Exact inverse of depthFromPressure: Newton iteration on eq. 25, started from
// Saunders (1981). depthFromPressure(pressureFromDepth(z)) == z to 1e-9 m.
double pressureFromDepth(double depth_m, double latitude_deg = kDefaultLatitude_deg);

// Saunders (1981) closed form, kept for comparison with tools that use it
// (CSIRO sw_pres). It differs from the UNESCO inverse by up to ~8 dbar at
// 10000 m, 0.26 dbar at 1000 m.
double pressureFromDepthSaunders(double depth_m, double latitude_deg = kDefaultLatitude_deg);

// EOS-80 in-situ density [kg/m^3] at a depth, via pressureFromDepth.
double densityAtDepth(double salinity_psu, double temperature_degC, double depth_m,
                      double latitude_deg = kDefaultLatitude_deg,
                      TempScale scale = TempScale::ITS90);

}  // namespace auv::seawater
