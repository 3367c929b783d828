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

void scaleFields(nlohmann::json& section, std::initializer_list<const char*> keys, double s) {
  for (const char* k : keys)
    if (section.contains(k) && section[k].is_number()) section[k] = section[k].get<double>() * s;
}

const CalibrationValue* calibrationOf(const ModelCheckResult& r, const char* id) {
  for (const CalibrationValue& c : r.calibration)
    if (c.id == id && c.identified) return &c;
  return nullptr;
}

// Identified calibration constants into the sections the simulator reads
// them from; each listed under model_check.calibrated. Returns false when
// the profile lacks the section (nothing written for that constant).
void writeCalibration(nlohmann::json& out, const ModelCheckResult& r, const std::string& log_name) {
  nlohmann::json& mc = out["model_check"];
  auto record = [&](const CalibrationValue& c, const std::string& where) {
    if (!mc.contains("calibrated")) mc["calibrated"] = nlohmann::json::array();
    mc["calibrated"].push_back({{"id", c.id},
                                {"value", c.value},
                                {"sigma", c.sigma},
                                {"unit", c.unit},
                                {"profile_value", c.profile_value},
                                {"written_to", where},
                                {"log", log_name}});
  };
  const bool hydro = out.contains("hydrodynamics") && out["hydrodynamics"].is_object();
  if (const CalibrationValue* c = calibrationOf(r, "propeller_torque");
      c && has(out, "sim_assumptions", "prop_KQ0") && has(out, "actuators", "propeller")) {
    sim::Propeller p;
    p.diameter_m = out["actuators"]["propeller"].value("diameter_m", 0.0);
    if (p.diameter_m > 0.0) {
      // The calibrated torque is the vehicle's whole torque: it replaces the
      // profile's K_Q0 and any torque accepted earlier as a term.
      const double signedKQ = propKQ0ForTorque(p, c->value);
      out["sim_assumptions"]["prop_KQ0"] = std::min(1.0, std::abs(signedKQ));
      out["sim_assumptions"]["prop_torque_sign"] = signedKQ < 0 ? -1.0 : 1.0;
      if (mc.contains("terms")) mc["terms"].erase("propeller_torque");
      record(*c, "sim_assumptions.prop_KQ0");
    }
  }
  if (const CalibrationValue* c = calibrationOf(r, "heave_derivatives"); c && hydro) {
    // The analysis's heave group leaves Z_ww to the crossflow group.
    if (c->from_analysis) {
      scaleFields(out["hydrodynamics"], {"Zw_prime", "Zq_prime"}, c->value);
      record(*c, "hydrodynamics.Zw_prime, Zq_prime");
    } else {
      scaleFields(out["hydrodynamics"], {"Zw_prime", "Zq_prime", "Zww_kg_per_m"}, c->value);
      record(*c, "hydrodynamics.Zw_prime, Zq_prime, Zww_kg_per_m");
    }
  }
  if (const CalibrationValue* c = calibrationOf(r, "net_pitch_moment_derivative"); c && hydro) {
    // The simulator adds the Munk moment (X_udot - Z_wdot) u w to M_w' itself,
    // unless the profile's M_w' holds it.
    nlohmann::json& h = out["hydrodynamics"];
    const double L = h.value("reference_length_m", numberAt(out, "hull", "length_m", 1.0));
    const double added = h.value("munk_moment", std::string("added")) == "inside_Mw" ? 0.0 : 1.0;
    const double munkPrime = added * (h.value("Xudot_kg", 0.0) - h.value("Zwdot_kg", 0.0)) / (0.5 * 1025.0 * L * L * L);
    h["Mw_prime"] = c->value - munkPrime;
    record(*c, "hydrodynamics.Mw_prime");
  }
  if (const CalibrationValue* c = calibrationOf(r, "crossflow_pitch_moment"); c && hydro) {
    if (c->from_analysis) {
      scaleFields(out["hydrodynamics"], {"Zww_kg_per_m", "Mww_kg", "Mqq_kgm2_per_rad2"}, c->value);
      record(*c, "hydrodynamics.Zww_kg_per_m, Mww_kg, Mqq_kgm2_per_rad2");
    } else {
      scaleFields(out["hydrodynamics"], {"Mww_kg"}, c->value);
      record(*c, "hydrodynamics.Mww_kg");
    }
  }
  if (const CalibrationValue* c = calibrationOf(r, "surge_drag"); c && hydro) {
    scaleFields(out["hydrodynamics"], {"Xu_kg_per_s", "Xuu_kg_per_m"}, c->value);
    record(*c, "hydrodynamics.Xu_kg_per_s, Xuu_kg_per_m");
  }
  if (const CalibrationValue* c = calibrationOf(r, "pitch_damping"); c && hydro) {
    scaleFields(out["hydrodynamics"], {"Mq_prime"}, c->value);
    record(*c, "hydrodynamics.Mq_prime");
  }
  if (const CalibrationValue* c = calibrationOf(r, "roll_damping"); c && out.contains("sim_assumptions")) {
    scaleFields(out["sim_assumptions"], {"Kp_kgm2_per_s", "Kpp_kgm2"}, c->value);
    record(*c, "sim_assumptions.Kp_kgm2_per_s, Kpp_kgm2");
  }
  if (const CalibrationValue* c = calibrationOf(r, "bg"); c && (out.contains("bg_mm") || out.contains("cg_mm"))) {
    // The check's BG is as flown (installed weights included); the
    // difference from the profile's is the base vehicle's too.
    const double dz_mm = 1e3 * (c->value - c->profile_value);
    if (out.contains("cg_mm") && out["cg_mm"].contains("z_mm")) {
      out["cg_mm"]["z_mm"] = out["cg_mm"]["z_mm"].get<double>() + dz_mm;
      record(*c, "cg_mm.z_mm");
    } else if (out.contains("bg_mm") && out["bg_mm"].is_number()) {
      out["bg_mm"] = out["bg_mm"].get<double>() + dz_mm;
      record(*c, "bg_mm");
    }
  }
  if (const CalibrationValue* c = calibrationOf(r, "stern_plane_effectiveness"); c && has(out, "actuators", "stern_planes")) {
    scaleFields(out["actuators"]["stern_planes"], {"X_uudd_kg_per_m_deg2", "Z_uud_kg_per_m_deg", "M_uud_kg_per_deg"}, c->value);
    record(*c, "actuators.stern_planes");
  }
}

}  // namespace

bool hasCalibrationToWrite(const ModelCheckResult& r) {
  return std::any_of(r.calibration.begin(), r.calibration.end(), [](const CalibrationValue& c) { return c.identified; });
}

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
    const double increment = m.value - m.profile_value;  // display unit
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
      out["flight_model"]["pitch_offset_deg"] = numberAt(out, "flight_model", "pitch_offset_deg", 0.0) - increment;
      where = "flight_model.pitch_offset_deg";
    } else {
      const double old = mc["terms"].contains(m.id) ? mc["terms"][m.id].get<double>() : 0.0;
      mc["terms"][m.id] = old + increment;
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
                              {"channel", channelName(m.channel)},
                              {"profile_value", m.profile_value}});
  }
  writeCalibration(out, r, log_name);
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
