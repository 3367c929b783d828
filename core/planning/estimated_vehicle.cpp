#include "planning/estimated_vehicle.h"

#include <cmath>

#include "common/input_error.h"
#include "seawater/seawater.h"

namespace auv {

ResolvedPoint resolvePoint(const HullModel& hull, const PlannedWater& w) {
  ResolvedPoint p;
  p.planned = w;
  p.state = resolveWater(w);
  p.displaced_kg = displacedMassKg(hull, p.state);
  return p;
}

double displacedSigmaKg(const HullModel& hull, const PlannedWater& w, double t_sigma, double s_sigma) {
  // Central differences one sigma either side, clamped into EOS-80's range
  // (the one-sided step is then doubled so the slope stays a slope).
  auto at = [&](double t, double s) {
    PlannedWater x = w;
    x.temperature_degC = t;
    x.salinity_psu = s;
    return displacedMassKg(hull, resolveWater(x));
  };
  auto part = [&](double lo_t, double hi_t, double lo_s, double hi_s, double span, double sigma) {
    if (!(sigma > 0.0) || !(span > 0.0)) return 0.0;
    return (at(hi_t, hi_s) - at(lo_t, lo_s)) / span * sigma;
  };
  const double t0 = w.temperature_degC, s0 = w.salinity_psu;
  const double tl = std::max(-2.0, t0 - t_sigma), th = std::min(40.0, t0 + t_sigma);
  const double sl = std::max(0.0, s0 - s_sigma), sh = std::min(42.0, s0 + s_sigma);
  const double dT = part(tl, th, s0, s0, th - tl, t_sigma);
  const double dS = part(t0, t0, sl, sh, sh - sl, s_sigma);
  return std::hypot(dT, dS);
}

double hullLawSigmaKg(const HullModel& hull, const WaterState& log_water, const PlannedWater& w,
                      double compressibility_sigma_per_dbar, double thermal_expansion_sigma_per_degC) {
  const WaterState there = resolveWater(w);
  auto change = [&](const HullModel& h) { return displacedMassKg(h, there) - displacedMassKg(h, log_water); };
  HullModel k = hull, a = hull;
  k.compressibility_per_dbar += compressibility_sigma_per_dbar;
  a.thermal_expansion_per_degC += thermal_expansion_sigma_per_degC;
  return std::hypot(change(k) - change(hull), change(a) - change(hull));
}

EstimatedVehicle estimatedVehicle(const VehicleProfile& v, const HullModel& hull, const TrimEstimate& e) {
  auto finite = [](double x) { return std::isfinite(x); };
  if (!finite(e.net_buoyancy_kg)) throw InputError("net_buoyancy_kg", "not a number", "give the analysis result");
  if (!finite(e.net_buoyancy_sigma_kg) || e.net_buoyancy_sigma_kg < 0.0) {
    throw InputError("net_buoyancy_sigma_kg", "must be a number >= 0", "give the analysis's 1-sigma in kg");
  }
  if (!(e.water.density_kgm3 > 900.0) || !(e.water.density_kgm3 < 1100.0)) {
    throw InputError("water.density_kgm3", "not a seawater density", "give the in-situ density of the log, 900-1100");
  }
  if (!finite(e.water.temperature_degC) || !finite(e.water.pressure_dbar) || e.water.pressure_dbar < 0.0) {
    throw InputError("water", "temperature and pressure of the log must be numbers (pressure >= 0)",
                     "give the water the net buoyancy was measured in");
  }
  for (const auto& [name, c, s] : {std::tuple{"cg_offset_mm.x", e.cg_x_m, e.cg_x_sigma_m},
                                   std::tuple{"cg_offset_mm.y", e.cg_y_m, e.cg_y_sigma_m}}) {
    if ((c && !finite(*c)) || !finite(s) || s < 0.0) {
      throw InputError(name, "offset and sigma must be numbers, sigma >= 0", "give the analysis result in mm");
    }
    if (c && std::abs(*c) > 0.5) throw InputError(name, "offset beyond 500 mm", "check the units (mm)");
  }
  EstimatedVehicle out;
  out.cb_m = v.cb_m;
  out.log_displaced_kg = displacedMassKg(hull, e.water);
  const double mass = out.log_displaced_kg - e.net_buoyancy_kg;
  if (!(mass > 0.0)) throw InputError("net_buoyancy_kg", "implies a non-positive mass", "check the analysis result");
  out.mass_sigma_kg = e.net_buoyancy_sigma_kg;
  out.cg_x_assumed = !e.cg_x_m;
  out.cg_y_assumed = !e.cg_y_m;
  const Eigen::Vector3d cg(v.cb_m.x() + e.cg_x_m.value_or(0.0), v.cb_m.y() + e.cg_y_m.value_or(0.0),
                           v.cb_m.z() + e.bg_m.value_or(v.bg_m));
  out.mass.mass_kg = mass;
  out.mass.cg_m = cg;
  out.mass.moment_kgm = mass * cg;
  return out;
}

}  // namespace auv
