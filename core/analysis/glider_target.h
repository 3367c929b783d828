#pragma once
// The water a glider is ballasted for: density, pressure and temperature of
// the next deployment's water, where the glider must be neutral with its
// buoyancy engine at its zero reference. Given on the command line
// (--target-density/--target-pressure/--target-temperature, or
// --target-depth with the log's own CTD profile supplying T, S and p there),
// else the log's own water at the bottom of its deepest yo. `basis` says in
// words where each number came from, for the report.
#include <optional>
#include <string>

#include "missionlog/mission_log.h"

namespace auv::analysis {

struct GliderTargetRequest {
  std::optional<double> density_kgm3;
  std::optional<double> pressure_dbar;
  std::optional<double> temperature_degC;
  std::optional<double> depth_m;  // T, S, p from the log's own profile at this depth
  bool any() const { return density_kgm3 || pressure_dbar || temperature_degC || depth_m; }
};

struct GliderTarget {
  double density_kgm3 = 0.0;
  double pressure_dbar = 0.0;
  double temperature_degC = 0.0;
  double salinity_psu = 0.0;  // NaN when not known (density given directly)
  std::string basis;
};

// Throws InputError naming the flag ("target-depth", ...) when the log cannot
// supply what is asked (no CTD, depth not reached, value out of range).
GliderTarget resolveGliderTarget(const MissionLog& log, const GliderTargetRequest& request, double latitude_deg);

// Hull volume model of the answer: V(p, T) = V0 (1 - kappa p) (1 + alpha (T - T_ref)),
// ballast inside the hull (no volume change), pump at zero: the kg to add so
// that rho_t V(p_t, T_t) = m_now + add.
double gliderMassToAddKg(double V0_m3, double kappa_per_dbar, double alpha_per_degC, double T_ref_degC,
                         const GliderTarget& target, double mass_now_kg);

}  // namespace auv::analysis
