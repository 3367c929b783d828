#pragma once
// How a segment's known buoyancy change would move if the hull law were off
// or the mass drifted (issue 11): the steady calibration carries an extra
// compressibility, an extra thermal expansion and a mass drift as groups
// with priors, so a profile whose hull law is wrong does not bend the heave
// groups it holds.
#include <cmath>
#include <vector>

#include "analysis/auv_trim_estimation.h"
#include "common/units.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis {

// The water the net buoyancy refers to (the log's mean).
struct HullLawReference {
  double density_kgm3 = 1025.0, temperature_degC = 20.0, pressure_dbar = 0.0;
};

// dB/d(kappa) and dB/d(alpha) of a segment's buoyancy change from the
// reference, with V = V0 (1 + alpha (T - T0)) (1 - kappa p): each is the
// segment's derivative minus the reference water's (the net buoyancy at the
// reference absorbs any constant). Segments without pressure or
// temperature get no lever.
inline void setHullLawLevers(const HullModel& h, const HullLawReference& ref, SteadySegmentMeans& s) {
  s.compressibility_lever_n = s.thermal_lever_n = 0.0;
  if (!std::isfinite(s.pressure_dbar) || !std::isfinite(s.temperature_degC) || !std::isfinite(s.density_kgm3)) return;
  auto dKappa = [&](double rho, double T, double p) {
    return -units::g0 * rho * h.volume_m3 * (1.0 + h.thermal_expansion_per_degC * (T - h.reference_temperature_degC)) * p;
  };
  auto dAlpha = [&](double rho, double T, double p) {
    return units::g0 * rho * h.volume_m3 * (T - h.reference_temperature_degC) * (1.0 - h.compressibility_per_dbar * p);
  };
  s.compressibility_lever_n = dKappa(s.density_kgm3, s.temperature_degC, s.pressure_dbar) -
                              dKappa(ref.density_kgm3, ref.temperature_degC, ref.pressure_dbar);
  s.thermal_lever_n = dAlpha(s.density_kgm3, s.temperature_degC, s.pressure_dbar) -
                      dAlpha(ref.density_kgm3, ref.temperature_degC, ref.pressure_dbar);
}

// d buoyancy_change_n / d(mass drift in kg/h) of the log's own segments:
// -g times the hours from their mean time (the net buoyancy is the log's
// mean). History segments keep none: their drift was another mission's.
inline void setDriftLevers(std::vector<SteadySegmentMeans>& segments) {
  double sum = 0.0;
  for (const SteadySegmentMeans& s : segments) sum += 0.5 * (s.start_s + s.end_s);
  const double t_ref = segments.empty() ? 0.0 : sum / static_cast<double>(segments.size());
  for (SteadySegmentMeans& s : segments) s.drift_lever_n = -units::g0 * (0.5 * (s.start_s + s.end_s) - t_ref) / 3600.0;
}

}  // namespace auv::analysis
