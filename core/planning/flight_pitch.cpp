#include "planning/flight_pitch.h"

#include <string>

#include "analysis/level_flight.h"
#include "common/units.h"

namespace auv {

namespace {

std::optional<analysis::SteadyHydroCoefficients> coefficients(const VehicleProfile& v,
                                                              const std::optional<nlohmann::json>& calibrated) {
  std::string why;
  if (!calibrated) return analysis::steadyHydroFromProfile(v, why);
  VehicleProfile k = v;
  k.sections["hydrodynamics"] = *calibrated;
  return analysis::steadyHydroFromProfile(k, why);
}

}  // namespace

std::optional<double> planeLeverM(const VehicleProfile& v, const std::optional<nlohmann::json>& calibrated) {
  const auto c = coefficients(v, calibrated);
  if (!c || !c->has_planes || c->Z_e_per_deg == 0.0) return std::nullopt;
  return c->M_e_per_deg / c->Z_e_per_deg;
}

std::optional<double> flightPitchDeg(const VehicleProfile& v, double speed_mps, double mass_kg,
                                     const Eigen::Vector3d& cg_m, const PlannedPointResult& operating,
                                     const std::optional<nlohmann::json>& calibrated) {
  if (!(speed_mps > 0.0)) return std::nullopt;
  const auto c = coefficients(v, calibrated);
  if (!c) return std::nullopt;
  const analysis::LevelFlight f = analysis::solveLevelFlight(
      *c, {units::g0 * mass_kg, units::g0 * operating.displaced_kg, cg_m.x() - v.cb_m.x(), cg_m.z() - v.cb_m.z(),
           speed_mps, operating.state.density_kgm3, 0.0});
  if (!f.ok) return std::nullopt;
  return units::radToDeg(f.pitch_rad);
}

}  // namespace auv
