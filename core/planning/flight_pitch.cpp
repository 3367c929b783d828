#include "planning/flight_pitch.h"

#include <string>

#include "analysis/level_flight.h"
#include "common/units.h"

namespace auv {

std::optional<double> flightPitchDeg(const VehicleProfile& v, double speed_mps, double mass_kg,
                                     const Eigen::Vector3d& cg_m, const PlannedPointResult& operating) {
  if (!(speed_mps > 0.0)) return std::nullopt;
  std::string why;
  const auto c = analysis::steadyHydroFromProfile(v, why);
  if (!c) return std::nullopt;
  const analysis::LevelFlight f = analysis::solveLevelFlight(
      *c, {units::g0 * mass_kg, units::g0 * operating.displaced_kg, cg_m.x() - v.cb_m.x(), cg_m.z() - v.cb_m.z(),
           speed_mps, operating.state.density_kgm3, 0.0});
  if (!f.ok) return std::nullopt;
  return units::radToDeg(f.pitch_rad);
}

}  // namespace auv
