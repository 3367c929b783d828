#include "vehicle/profile_loader.h"

#include <algorithm>
#include <set>

#include "common/units.h"
#include "vehicle/json_reader.h"

namespace auv {
namespace {

constexpr std::string_view kProfileDoc = "docs/formats/vehicle-profile.md";

Eigen::Vector3d readPointMm(const JsonReader& r) {
  r.refuseUnknownKeys({"x_mm", "y_mm", "z_mm"}, kProfileDoc);
  return {units::mmToM(r.numberIn("x_mm", -1e5, 1e5)), units::mmToM(r.numberIn("y_mm", -1e5, 1e5)),
          units::mmToM(r.numberIn("z_mm", -1e5, 1e5, 0.0))};
}

HullModel readHull(const JsonReader& root, double mass_kg) {
  const JsonReader h = root.child("hull");
  h.refuseUnknownKeys({"length_m", "diameter_m", "volume_m3", "weight_in_water_kg", "weighing_density_kgm3",
                       "reference_temperature_degC", "thermal_expansion_per_degC", "compressibility_per_dbar"},
                      kProfileDoc);
  HullModel hull;
  hull.length_m = h.numberIn("length_m", 0.1, 100.0);
  hull.diameter_m = h.numberIn("diameter_m", 0.01, 20.0);
  hull.reference_temperature_degC = h.numberIn("reference_temperature_degC", -5.0, 40.0, 20.0);
  hull.thermal_expansion_per_degC = h.numberIn("thermal_expansion_per_degC", 0.0, 1e-3, 0.0);
  hull.compressibility_per_dbar = h.numberIn("compressibility_per_dbar", 0.0, 1e-4, 0.0);
  if (h.has("volume_m3")) {
    hull.volume_m3 = h.numberIn("volume_m3", 1e-4, 1e3);
  } else if (h.has("weight_in_water_kg")) {
    // Thesis App. A: V = (m_air - m_water) / rho, rho the density it was weighed in.
    const double w_water = h.numberIn("weight_in_water_kg", -1e5, 1e5);
    const double rho = h.numberIn("weighing_density_kgm3", 990.0, 1050.0);
    hull.volume_m3 = (mass_kg - w_water) / rho;
    if (hull.volume_m3 <= 0.0) {
      h.fail("weight_in_water_kg", "gives a non-positive hull volume",
             "weight in water must be less than the mass in air");
    }
  } else {
    h.fail("volume_m3", "missing hull volume",
           "give \"volume_m3\" or \"weight_in_water_kg\" with \"weighing_density_kgm3\"");
  }
  return hull;
}

}  // namespace

const AdjustmentPoint* VehicleProfile::findPoint(const std::string& point_name) const {
  for (const auto& p : points) {
    if (p.name == point_name) return &p;
  }
  return nullptr;
}

namespace {

VehicleProfile fromJson(const nlohmann::json& doc, const std::string& file) {
  const JsonReader root(doc, file);
  // The sections after "spec" belong to specialised modules (weighing, Slocum
  // layout, glider flight, simulator, model check), which read them by name.
  root.refuseUnknownKeys({"id", "name", "kind", "source", "comment", "mass_in_air_kg", "hull", "cb_mm", "cg_mm", "bg_mm",
                          "adjustment_points", "weight_kit", "spec", "weighing", "slocum", "glider_flight",
                          "flight_model", "seaglider", "hydrodynamics", "actuators", "sim_assumptions", "autopilot", "model_check"},
                         kProfileDoc);
  VehicleProfile v;
  v.file = file;
  v.id = root.text("id");
  v.name = root.text("name", v.id);
  v.kind = root.text("kind");
  if (v.kind != "auv" && v.kind != "glider") {
    root.fail("kind", "unknown vehicle kind '" + v.kind + "'", "use \"auv\" or \"glider\"");
  }
  v.source = root.text("source", "");
  v.mass_kg = root.numberIn("mass_in_air_kg", 0.1, 1e5);
  v.hull = readHull(root, v.mass_kg);
  v.cb_m = readPointMm(root.child("cb_mm"));
  if (auto cg = root.optionalChild("cg_mm")) v.cg_m = readPointMm(*cg);
  v.bg_m = units::mmToM(root.numberIn("bg_mm", -500.0, 500.0, 0.0));

  std::set<std::string> names;
  if (root.has("adjustment_points")) {
    for (const auto& p : root.array("adjustment_points")) {
      p.refuseUnknownKeys({"name", "label", "x_mm", "y_mm", "z_mm", "capacity_kg"}, kProfileDoc);
      AdjustmentPoint ap;
      ap.name = p.text("name");
      if (!names.insert(ap.name).second) {
        p.fail("name", "duplicate adjustment point '" + ap.name + "'", "give every point a unique name");
      }
      ap.label = p.text("label", ap.name);
      ap.position_m = {units::mmToM(p.numberIn("x_mm", -1e5, 1e5)), units::mmToM(p.numberIn("y_mm", -1e5, 1e5)),
                       units::mmToM(p.numberIn("z_mm", -1e5, 1e5, 0.0))};
      ap.capacity_kg = p.numberIn("capacity_kg", 0.0, 1e4);
      v.points.push_back(ap);
    }
  }
  if (auto kit = root.optionalChild("weight_kit")) {
    kit->refuseUnknownKeys({"pieces_kg", "optional_pieces_kg"}, kProfileDoc);
    v.kit.pieces_kg = kit->numbers("pieces_kg");
    if (kit->has("optional_pieces_kg")) v.kit.optional_pieces_kg = kit->numbers("optional_pieces_kg");
    for (double m : v.kit.pieces_kg) {
      if (!(m > 0.0)) kit->fail("pieces_kg", "piece sizes must be positive", "remove zero or negative sizes");
    }
    for (double m : v.kit.optional_pieces_kg) {
      if (!(m > 0.0)) {
        kit->fail("optional_pieces_kg", "piece sizes must be positive", "remove zero or negative sizes");
      }
    }
    std::sort(v.kit.pieces_kg.begin(), v.kit.pieces_kg.end());
  }
  if (auto spec = root.optionalChild("spec")) {
    spec->refuseUnknownKeys({"net_buoyancy_min_kg", "net_buoyancy_max_kg", "pitch_tolerance_deg", "roll_tolerance_deg"},
                            kProfileDoc);
    v.spec.net_buoyancy_min_kg = spec->numberIn("net_buoyancy_min_kg", -100.0, 100.0, 0.0);
    v.spec.net_buoyancy_max_kg = spec->numberIn("net_buoyancy_max_kg", -100.0, 100.0, 1.2);
    v.spec.pitch_tolerance_deg = spec->numberIn("pitch_tolerance_deg", 0.0, 45.0, 0.5);
    v.spec.roll_tolerance_deg = spec->numberIn("roll_tolerance_deg", 0.0, 45.0, 0.1);
    if (v.spec.net_buoyancy_max_kg < v.spec.net_buoyancy_min_kg) {
      spec->fail("net_buoyancy_max_kg", "is below net_buoyancy_min_kg", "swap or correct the band");
    }
  }
  if (auto w = root.optionalChild("weighing")) {
    w->refuseUnknownKeys({"method", "rope_y_m", "scale_resolution_kg", "sum_tolerance_kg"}, kProfileDoc);
  }
  // Everything else that is an object belongs to a specialised module.
  static const std::set<std::string> generic = {"hull", "cb_mm", "cg_mm", "weight_kit", "spec"};
  for (const auto& [key, value] : doc.items()) {
    if (value.is_object() && !generic.count(key)) v.sections[key] = value;
  }
  return v;
}

}  // namespace

VehicleProfile parseVehicleProfile(const std::string& json_text, const std::string& file) {
  return fromJson(JsonReader::parseText(json_text, file), file);
}

VehicleProfile loadVehicleProfile(const std::string& file) {
  return fromJson(JsonReader::parseFile(file), file);
}

}  // namespace auv
