#include "vehicle/profile_writer.h"

#include <cmath>

#include "common/units.h"

namespace auv {
namespace {

// A length in mm that the loader's mm -> m conversion turns back into
// exactly `m` (x * 1e3 * 1e-3 is not always x).
double exactMm(double m) {
  double mm = units::mToMm(m);
  for (int k = 0; k < 8 && units::mmToM(mm) != m; ++k)
    mm = std::nextafter(mm, units::mmToM(mm) < m ? HUGE_VAL : -HUGE_VAL);
  return mm;
}

nlohmann::json pointMm(const Eigen::Vector3d& p) {
  return {{"x_mm", exactMm(p.x())}, {"y_mm", exactMm(p.y())}, {"z_mm", exactMm(p.z())}};
}

}  // namespace

nlohmann::json profileToJson(const VehicleProfile& v) {
  nlohmann::json j = nlohmann::json::object();
  // Sections first: the generic fields below are the loader's, never a section's.
  for (const auto& [key, value] : v.sections.items()) j[key] = value;
  j["id"] = v.id;
  j["name"] = v.name;
  j["kind"] = v.kind;
  j["source"] = v.source;
  j["mass_in_air_kg"] = v.mass_kg;
  const HullModel& h = v.hull;
  j["hull"] = {{"length_m", h.length_m},
               {"diameter_m", h.diameter_m},
               {"volume_m3", h.volume_m3},
               {"reference_temperature_degC", h.reference_temperature_degC},
               {"thermal_expansion_per_degC", h.thermal_expansion_per_degC},
               {"compressibility_per_dbar", h.compressibility_per_dbar}};
  j["cb_mm"] = pointMm(v.cb_m);
  if (v.cg_m) j["cg_mm"] = pointMm(*v.cg_m);
  j["bg_mm"] = exactMm(v.bg_m);
  nlohmann::json points = nlohmann::json::array();
  for (const AdjustmentPoint& p : v.points) {
    nlohmann::json q = pointMm(p.position_m);
    q["name"] = p.name;
    q["label"] = p.label;
    q["capacity_kg"] = p.capacity_kg;
    points.push_back(q);
  }
  j["adjustment_points"] = points;
  j["weight_kit"] = {{"pieces_kg", v.kit.pieces_kg}};
  if (!v.kit.optional_pieces_kg.empty()) j["weight_kit"]["optional_pieces_kg"] = v.kit.optional_pieces_kg;
  j["spec"] = {{"net_buoyancy_min_kg", v.spec.net_buoyancy_min_kg},
               {"net_buoyancy_max_kg", v.spec.net_buoyancy_max_kg},
               {"pitch_tolerance_deg", v.spec.pitch_tolerance_deg},
               {"roll_tolerance_deg", v.spec.roll_tolerance_deg}};
  return j;
}

}  // namespace auv
