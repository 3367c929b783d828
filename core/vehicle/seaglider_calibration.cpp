#include "vehicle/seaglider_calibration.h"

#include <filesystem>

#include "common/input_error.h"

namespace auv {

double SeagliderCalibration::get(const std::string& name) const {
  const auto it = values.find(name);
  if (it == values.end())
    throw InputError(name, "is not in " + file, "use a basestation per-dive file (p<glider><dive>.nc) with its sg_cal_* and log_* variables",
                     {file, 0, 0});
  return it->second;
}

nlohmann::json seagliderProfile(const SeagliderCalibration& c, const nlohmann::json& tpl) {
  nlohmann::json p = tpl;
  auto opt = [&](const char* name, double fallback) { return c.has(name) ? c.get(name) : fallback; };
  const std::string idNum = c.has("log_ID") ? std::to_string(static_cast<int>(c.get("log_ID"))) : "";
  p["id"] = "sg" + idNum;
  p["name"] = "Seaglider SG" + idNum;
  const double mass = c.get("sg_cal_mass");
  const double volmax = c.get("sg_cal_volmax");
  const double cvbd = opt("log_C_VBD", 0.0), vmin = opt("log_VBD_MIN", 0.0), cnv = opt("log_VBD_CNV", -0.2453);
  const double vbdbias = opt("sg_cal_vbdbias", 0.0);
  const double v0_cm3 = volmax + (cvbd - vmin) * cnv - vbdbias;
  p["source"] = "Made by 'auvballast profile --from " + std::filesystem::path(c.file).filename().string() +
                "': basestation sg_cal_* (mass, volmax, vbdbias, hd_a/b/c/s, abs_compress, therm_expan, temp_ref, rho0) and "
                "log_* piloting parameters of that dive. Hull volume = volmax + (C_VBD - VBD_MIN) VBD_CNV - vbdbias = " +
                std::to_string(v0_cm3) + " cm3 (the VBD at its $C_VBD set point). Length, diameter, lead capacity and the "
                "acceptance band come from the template: edit them for your glider.";
  p["mass_in_air_kg"] = mass;
  p["hull"]["volume_m3"] = v0_cm3 * 1e-6;
  p["hull"]["reference_temperature_degC"] = opt("sg_cal_temp_ref", 15.0);
  p["hull"]["thermal_expansion_per_degC"] = opt("sg_cal_therm_expan", 7.05e-5);
  p["hull"]["compressibility_per_dbar"] = opt("sg_cal_abs_compress", 4.1e-6);
  auto& f = p["flight_model"];
  f["form"] = "seaglider";
  f["hd_a"] = opt("sg_cal_hd_a", 3.8e-3);
  f["hd_b"] = opt("sg_cal_hd_b", 1.0e-2);
  f["hd_c"] = opt("sg_cal_hd_c", 1.0e-5);
  f["hd_s"] = opt("sg_cal_hd_s", -0.25);
  f["rho0_kgm3"] = opt("sg_cal_rho0", 1027.5);
  f["compressibility_per_dbar"] = opt("sg_cal_abs_compress", 4.1e-6);
  auto& s = p["seaglider"];
  s["C_VBD"] = cvbd;
  s["VBD_MIN"] = vmin;
  s["VBD_MAX"] = opt("log_VBD_MAX", 4000.0);
  s["VBD_CNV_cm3_per_count"] = cnv;
  s["C_PITCH"] = opt("log_C_PITCH", 2000.0);
  s["PITCH_CNV_cm_per_count"] = opt("log_PITCH_CNV", 0.00313);
  s["PITCH_MIN"] = opt("log_PITCH_MIN", 0.0);
  s["PITCH_MAX"] = opt("log_PITCH_MAX", 4000.0);
  s["volmax_cm3"] = volmax;
  s["vbdbias_cm3"] = vbdbias;
  return p;
}

}  // namespace auv
