#pragma once
// SI inside the core. These are the only conversions; front ends call them at
// the edges so that no module ever sees millimetres or degrees in a formula.
#include <numbers>

namespace auv::units {

// Standard gravity (CGPM 1901). Scales are calibrated against it, so a crane
// scale reading in "kg" is force / g0.
inline constexpr double g0 = 9.80665;  // m/s^2

inline constexpr double mmToM(double mm) { return mm * 1e-3; }
inline constexpr double mToMm(double m) { return m * 1e3; }
inline constexpr double degToRad(double deg) { return deg * std::numbers::pi / 180.0; }
inline constexpr double radToDeg(double rad) { return rad * 180.0 / std::numbers::pi; }
inline constexpr double newtonToKgf(double n) { return n / g0; }
inline constexpr double kgfToNewton(double kgf) { return kgf * g0; }
// Sea pressure: 1 dbar = 1e4 Pa.
inline constexpr double dbarToPa(double dbar) { return dbar * 1e4; }
inline constexpr double paToDbar(double pa) { return pa * 1e-4; }
inline constexpr double barToDbar(double bar) { return bar * 10.0; }

}  // namespace auv::units
