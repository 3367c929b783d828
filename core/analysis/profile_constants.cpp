#include "analysis/profile_constants.h"

#include "analysis/analysis_messages.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "common/input_error.h"
#include "common/units.h"
#include "sim/model_loader.h"
#include "vehicle/json_reader.h"

namespace auv::analysis {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double parseNumberAfter(const std::string& s, std::size_t pos) {
  const char* begin = s.c_str() + pos;
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  return end == begin ? kNaN : v;
}

double profileTorqueAt100Rpm(const VehicleProfile& v, double rho) {
  if (!v.sections.contains("sim_assumptions") || !v.sections.contains("actuators")) return 0.0;
  const nlohmann::json& a = v.sections["sim_assumptions"];
  const nlohmann::json& act = v.sections["actuators"];
  if (!a.contains("prop_KQ0") || !act.contains("propeller") || !act["propeller"].contains("diameter_m")) return 0.0;
  if (!a["prop_KQ0"].is_number() || !act["propeller"]["diameter_m"].is_number()) return 0.0;
  const double n = 100.0 / 60.0, D = act["propeller"]["diameter_m"].get<double>();
  return rho * n * n * std::pow(D, 5) * a["prop_KQ0"].get<double>();
}

std::optional<AuvTrimContext::PropellerLaw> propellerLawFromProfile(const VehicleProfile& v) {
  if (!v.sections.contains("actuators") || !v.sections["actuators"].contains("propeller")) return std::nullopt;
  const nlohmann::json& p = v.sections["actuators"]["propeller"];
  auto num = [&](const char* k, double fallback) { return p.contains(k) && p[k].is_number() ? p[k].get<double>() : fallback; };
  AuvTrimContext::PropellerLaw law;
  law.diameter_m = num("diameter_m", 0.0);
  law.c1 = num("c_prop1", 0.0);
  law.c2 = num("c_prop2", 1.0);
  law.wake_fraction = num("wake_fraction", 0.0);
  if (!(law.diameter_m > 0.0) || !(law.c1 > 0.0)) return std::nullopt;
  return law;
}

SeagliderCalibration seagliderCalibrationOf(const MissionLog& log, const std::string& file) {
  SeagliderCalibration c{file, log.seagliderConstants()};
  for (const char* need : {"sg_cal_mass", "sg_cal_volmax"})
    if (!c.has(need))
      throw InputError("from", "'" + file + "' has no " + need + " (it is not a Seaglider basestation per-dive file)",
                       "give a Seaglider per-dive file such as p1710100.nc, with its sg_cal_* and log_* variables");
  return c;
}

std::optional<double> latitudeFromMetadata(const MissionLog& log) {
  for (const char* key : {"latitude", "lat"}) {
    if (const std::string* v = log.metadataValue(key)) {
      const double x = parseNumberAfter(*v, 0);
      if (x >= -90 && x <= 90) return x;
    }
  }
  if (const std::string* v = log.metadataValue("position")) {
    const std::size_t k = v->find("lat");
    if (k != std::string::npos) {
      std::size_t q = k + 3;
      while (q < v->size() && !(std::isdigit(static_cast<unsigned char>((*v)[q])) || (*v)[q] == '-' || (*v)[q] == '+')) ++q;
      const double x = parseNumberAfter(*v, q);
      if (x >= -90 && x <= 90) return x;
    }
  }
  return std::nullopt;
}

GliderFlightConstants gliderConstantsFromProfile(const VehicleProfile& v, std::vector<Message>& notes) {
  GliderFlightConstants c;
  c.mass_kg = v.mass_kg;
  c.thermal_expansion_per_degC = v.hull.thermal_expansion_per_degC;
  c.reference_temperature_degC = v.hull.reference_temperature_degC;
  c.compressibility_per_dbar = v.hull.compressibility_per_dbar;
  if (v.sections.contains("flight_model")) {
    const JsonReader f(v.sections["flight_model"], v.file, "flight_model");
    c.wing_area_m2 = f.numberIn("wing_area_m2", 1e-4, 100.0, c.wing_area_m2);
    c.lift_slope_per_rad = f.numberIn("lift_slope_per_rad", 0.01, 100.0, c.lift_slope_per_rad);
    c.induced_drag_per_rad2 = f.numberIn("induced_drag_per_rad2", 0.0, 1000.0, c.induced_drag_per_rad2);
    if (f.has("compressibility_per_dbar")) c.compressibility_per_dbar = f.numberIn("compressibility_per_dbar", 0.0, 1e-3);
    c.pitch_scale = f.numberIn("pitch_scale", 0.1, 10.0, 1.0);
    const std::string form = f.text("form", "slocum");
    if (form == "seaglider") {
      c.form = GlideForm::kSeaglider;
      c.hd_a_per_deg = f.numberIn("hd_a", 1e-6, 1.0);
      c.drag_start = f.numberIn("hd_b", 1e-5, 1.0);
      c.hd_c_per_deg2 = f.numberIn("hd_c", 1e-9, 1.0);
      c.hd_s = f.numberIn("hd_s", -0.9, 0.0, -0.25);
      c.hull_length_m = f.numberIn("hull_length_m", 0.5, 5.0, 1.8);
      c.rho0_kgm3 = f.numberIn("rho0_kgm3", 990.0, 1080.0, 1027.5);
    } else if (form != "slocum") {
      f.fail("form", "unknown hydrodynamic form '" + form + "'", "use \"slocum\" (gliderflight) or \"seaglider\" (hd_a, hd_b, hd_c)");
    } else {
      c.drag_start = f.numberIn("Cd0", 1e-3, 3.0, 0.15);
    }
    c.pitch_offset_rad = units::degToRad(f.numberIn("pitch_offset_deg", -45.0, 45.0, 0.0));
  } else {
    notes.push_back(Message(msg::kGliderDefaultConstants));
  }
  if (!(c.compressibility_per_dbar > 0.0)) {
    c.compressibility_per_dbar = 5e-6;
    notes.push_back(Message(msg::kGliderDefaultCompressibility));
  }
  return c;
}

std::optional<sim::VehicleModel> simModelFromProfile(const VehicleProfile& v) {
  try {
    return sim::loadVehicleModel(v);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace auv::analysis
