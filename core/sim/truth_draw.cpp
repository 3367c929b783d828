#include "sim/truth_draw.h"

#include <cstdio>
#include <random>

namespace auv::sim {
namespace {

double u01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double between(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * u01(rng); }

}  // namespace

DrawnTruth drawTruth(std::uint64_t seed, const TruthDrawRanges& r) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 11);
  DrawnTruth d;
  d.seed = seed;
  d.heave_scale = between(rng, r.group_scale_min, r.group_scale_max);
  d.pitch_scale = between(rng, r.group_scale_min, r.group_scale_max);
  d.crossflow_scale = between(rng, r.group_scale_min, r.group_scale_max);
  d.plane_scale = between(rng, r.plane_min, r.plane_max);
  d.munk_inside_Mw = u01(rng) < r.munk_inside_probability;
  d.torque_factor = between(rng, 0.0, r.torque_factor_max);
  d.bg_m = between(rng, r.bg_min_m, r.bg_max_m);
  d.cg_x_m = between(rng, -r.cg_x_max_m, r.cg_x_max_m);
  d.cg_y_m = between(rng, -r.cg_y_max_m, r.cg_y_max_m);
  d.net_buoyancy_kg = between(rng, r.net_min_kg, r.net_max_kg);
  return d;
}

VehicleModel truthModel(const VehicleModel& nominal, const DrawnTruth& d) {
  VehicleModel m = nominal;
  Hydrodynamics& h = m.hydro;
  h.Zw_prime *= d.heave_scale;
  h.Zq_prime *= d.heave_scale;
  h.Mw_prime *= d.pitch_scale;
  h.Mq_prime *= d.pitch_scale;
  h.Zww_kg_per_m *= d.crossflow_scale;
  h.Mww_kg *= d.crossflow_scale;
  h.Mqq_kgm2 *= d.crossflow_scale;
  h.munk_factor = d.munk_inside_Mw ? 0.0 : 1.0;
  m.planes.X_uudd_per_deg2 *= d.plane_scale;
  m.planes.Z_uud_per_deg *= d.plane_scale;
  m.planes.M_uud_per_deg *= d.plane_scale;
  m.prop.KQ0 *= d.torque_factor;
  m.yaw.Nr_prime = h.Mq_prime;
  m.yaw.Nrr_kgm2 = h.Mqq_kgm2;
  m.yaw.N_uud_per_deg *= d.plane_scale;
  return m;
}

nlohmann::json truthHydrodynamicsDoc(const nlohmann::json& nominal_doc, const DrawnTruth& d) {
  nlohmann::json doc = nominal_doc;
  auto scale = [](nlohmann::json& obj, const char* key, double f) {
    if (obj.contains(key)) obj[key] = obj[key].get<double>() * f;
  };
  nlohmann::json& h = doc["hydrodynamics"];
  scale(h, "Zw_prime", d.heave_scale);
  scale(h, "Zq_prime", d.heave_scale);
  scale(h, "Mw_prime", d.pitch_scale);
  scale(h, "Mq_prime", d.pitch_scale);
  scale(h, "Zww_kg_per_m", d.crossflow_scale);
  scale(h, "Mww_kg", d.crossflow_scale);
  scale(h, "Mqq_kgm2_per_rad2", d.crossflow_scale);
  h["munk_moment"] = d.munk_inside_Mw ? "inside_Mw" : "added";
  nlohmann::json& planes = doc["actuators"]["stern_planes"];
  scale(planes, "X_uudd_kg_per_m_deg2", d.plane_scale);
  scale(planes, "Z_uud_kg_per_m_deg", d.plane_scale);
  scale(planes, "M_uud_kg_per_deg", d.plane_scale);
  scale(doc["sim_assumptions"], "prop_KQ0", d.torque_factor);
  return doc;
}

BallastError truthBallastError(const VehicleModel& truth, std::span<const MassItem> installed, double displaced_kg,
                               const DrawnTruth& d) {
  const FlownMass nominal = flownMass(truth, installed, std::nullopt, {}, 0.0);
  BallastError e;
  e.net_buoyancy_kg = d.net_buoyancy_kg - (displaced_kg - nominal.mass_kg);
  e.cg_shift_m = Eigen::Vector3d(d.cg_x_m, d.cg_y_m, d.bg_m) - nominal.r_g_m;
  return e;
}

std::string DrawnTruth::describe() const {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "seed %llu: heave x%.2f, pitch x%.2f, cross-flow x%.2f, planes x%.2f, Munk %s, torque x%.2f, "
                "BG %.1f mm, CG x %+.1f mm, y %+.2f mm, net %+.2f kg",
                static_cast<unsigned long long>(seed), heave_scale, pitch_scale, crossflow_scale, plane_scale,
                munk_inside_Mw ? "inside M_w" : "on top", torque_factor, bg_m * 1e3, cg_x_m * 1e3, cg_y_m * 1e3,
                net_buoyancy_kg);
  return buf;
}

}  // namespace auv::sim
