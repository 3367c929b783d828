#include "discrepancy/profile_update.h"

#include <algorithm>
#include <cmath>

#include "discrepancy/term_replay.h"
#include "vehicle/profile_loader.h"

namespace auv::discrepancy {

namespace {

double numberAt(const nlohmann::json& j, const char* a, const char* b, double fallback) {
  if (j.contains(a) && j[a].is_object() && j[a].contains(b) && j[a][b].is_number()) return j[a][b].get<double>();
  return fallback;
}

bool has(const nlohmann::json& j, const char* a, const char* b) {
  return j.contains(a) && j[a].is_object() && j[a].contains(b);
}

}  // namespace

nlohmann::json profileWithAcceptedTerms(const nlohmann::json& doc, const VehicleProfile& v, const ModelCheckResult& r,
                                        const std::string& log_name) {
  nlohmann::json out = doc;
  nlohmann::json& mc = out["model_check"];
  if (!mc.is_object()) mc = nlohmann::json::object();
  if (!mc.contains("terms")) mc["terms"] = nlohmann::json::object();
  if (!mc.contains("accepted")) mc["accepted"] = nlohmann::json::array();
  const bool glider = v.kind == "glider";
  for (const MissingPhysics& m : r.missing_physics) {
    const std::size_t k = *findTerm(m.id);
    const double si = r.accepted[k];  // SI increment
    std::string where;
    if (m.id == "hull_compressibility") {
      if (glider && has(out, "flight_model", "compressibility_per_dbar")) {
        out["flight_model"]["compressibility_per_dbar"] = numberAt(out, "flight_model", "compressibility_per_dbar", 0.0) + si;
        where = "flight_model.compressibility_per_dbar";
      } else {
        out["hull"]["compressibility_per_dbar"] = numberAt(out, "hull", "compressibility_per_dbar", 0.0) + si;
        where = "hull.compressibility_per_dbar";
      }
    } else if (m.id == "thermal_expansion") {
      out["hull"]["thermal_expansion_per_degC"] = numberAt(out, "hull", "thermal_expansion_per_degC", 0.0) + si;
      where = "hull.thermal_expansion_per_degC";
    } else if (m.id == "propeller_torque" && has(out, "sim_assumptions", "prop_KQ0") &&
               has(out, "actuators", "propeller") && out["actuators"]["propeller"].contains("diameter_m")) {
      sim::Propeller p;
      p.diameter_m = out["actuators"]["propeller"]["diameter_m"].get<double>();
      const double signedKQ = numberAt(out, "sim_assumptions", "prop_torque_sign", 1.0) *
                                  numberAt(out, "sim_assumptions", "prop_KQ0", 0.0) +
                              propKQ0ForTorque(p, si);
      out["sim_assumptions"]["prop_KQ0"] = std::abs(signedKQ);
      out["sim_assumptions"]["prop_torque_sign"] = signedKQ < 0 ? -1.0 : 1.0;
      where = "sim_assumptions.prop_KQ0";
    } else if (m.id == "quadratic_pitch_damping" && has(out, "hydrodynamics", "Mqq_kgm2_per_rad2")) {
      out["hydrodynamics"]["Mqq_kgm2_per_rad2"] = numberAt(out, "hydrodynamics", "Mqq_kgm2_per_rad2", 0.0) * (1.0 + si);
      where = "hydrodynamics.Mqq_kgm2_per_rad2";
    } else if (m.id == "pitch_sensor_bias" && glider) {
      out["flight_model"]["pitch_offset_deg"] = numberAt(out, "flight_model", "pitch_offset_deg", 0.0) - m.value;
      where = "flight_model.pitch_offset_deg";
    } else {
      const double old = mc["terms"].contains(m.id) ? mc["terms"][m.id].get<double>() : 0.0;
      mc["terms"][m.id] = old + m.value;
      where = "model_check.terms." + m.id;
    }
    mc["accepted"].push_back({{"id", m.id},
                              {"value", m.value},
                              {"sigma", m.sigma},
                              {"unit", m.unit},
                              {"written_to", where},
                              {"log", log_name},
                              {"rms_before", m.rms_before},
                              {"rms_after", m.rms_after},
                              {"channel", channelName(m.channel)}});
  }
  if (mc["terms"].empty()) mc.erase("terms");
  return out;
}

VehicleProfile vehicleFromStoredProfile(const nlohmann::json& profile_doc, const VehicleProfile& base,
                                        const std::string& source_name) {
  VehicleProfile v = parseVehicleProfile(profile_doc.dump(), source_name);
  for (const auto& [key, value] : base.sections.items())
    if (!v.sections.contains(key)) v.sections[key] = value;
  return v;
}

VehicleProfile vehicleWithAcceptedTerms(const nlohmann::json& doc, const VehicleProfile& v, const ModelCheckResult& result,
                                        const std::vector<std::string>& accepted_ids, const std::string& log_name,
                                        nlohmann::json* profile_doc_out) {
  // Companion sections first, so that terms written into them (e.g. the
  // pitch damping in "hydrodynamics") land on the full section.
  nlohmann::json full = doc;
  for (const auto& [key, value] : v.sections.items())
    if (!full.contains(key)) full[key] = value;
  ModelCheckResult chosen = result;
  chosen.missing_physics.clear();
  for (const MissingPhysics& m : result.missing_physics)
    if (std::find(accepted_ids.begin(), accepted_ids.end(), m.id) != accepted_ids.end()) chosen.missing_physics.push_back(m);
  const nlohmann::json out = profileWithAcceptedTerms(full, v, chosen, log_name);
  if (profile_doc_out) *profile_doc_out = out;
  return vehicleFromStoredProfile(out, v, v.file);
}

}  // namespace auv::discrepancy
