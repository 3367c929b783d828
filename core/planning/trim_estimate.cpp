#include "planning/trim_estimate.h"

#include <algorithm>
#include <cmath>

#include "common/units.h"
#include "seawater/seawater.h"
#include "vehicle/json_reader.h"

namespace auv {
namespace {

// A number, or nullopt for null/absent: the analysis writes null for what a
// log cannot determine.
std::optional<double> optionalNumber(const JsonReader& r, const std::string& key) {
  if (!r.has(key) || r.node()[key].is_null()) return std::nullopt;
  return r.number(key);
}

double requiredNumber(const JsonReader& r, const std::string& key, const std::string& why) {
  if (!r.has(key) || r.node()[key].is_null()) {
    r.fail(key, "missing or null: " + why, "run 'auvballast analyze' on a log with steady level flight, or give a report "
                                           "that contains it");
  }
  return r.number(key);
}

}  // namespace

TrimEstimate trimEstimateFromReport(const nlohmann::json& report, const std::string& file) {
  const JsonReader root(report, file);
  TrimEstimate e;
  e.net_buoyancy_kg = requiredNumber(root, "net_buoyancy_kg", "the planner needs the identified net buoyancy");
  e.net_buoyancy_sigma_kg = requiredNumber(root, "net_buoyancy_sigma_kg", "the safety margin needs its uncertainty");
  if (e.net_buoyancy_sigma_kg < 0.0) root.fail("net_buoyancy_sigma_kg", "must be >= 0", "write a 1-sigma value in kg");
  if (root.has("cg_offset_mm")) {
    const JsonReader cg = root.child("cg_offset_mm");
    const std::optional<JsonReader> sg = root.optionalChild("cg_offset_sigma_mm");
    if (auto x = optionalNumber(cg, "x")) {
      e.cg_x_m = units::mmToM(*x);
      if (sg) e.cg_x_sigma_m = units::mmToM(optionalNumber(*sg, "x").value_or(0.0));
    }
    if (auto y = optionalNumber(cg, "y")) {
      e.cg_y_m = units::mmToM(*y);
      if (sg) e.cg_y_sigma_m = units::mmToM(optionalNumber(*sg, "y").value_or(0.0));
    }
    if (root.has("cruise") && root.node()["cruise"].is_object()) {
      const JsonReader cr = root.child("cruise");
      e.cruise_speed_mps = optionalNumber(cr, "speed_mps").value_or(0.0);
      if (auto yc = optionalNumber(cr, "cg_y_mm")) {
        e.cg_y_m = units::mmToM(*yc);
        e.cg_y_sigma_m = units::mmToM(optionalNumber(cr, "cg_y_sigma_mm").value_or(0.0));
        e.cg_y_basis = "cruise";
        e.cruise_rpm = optionalNumber(cr, "prop_rpm").value_or(0.0);
      }
    }
    if (e.cg_x_sigma_m < 0.0 || e.cg_y_sigma_m < 0.0) {
      root.fail("cg_offset_sigma_mm", "sigmas must be >= 0", "write 1-sigma values in mm");
    }
  }
  const JsonReader w = root.child("water");
  e.water.temperature_degC = requiredNumber(w, "temperature_degC", "net buoyancy is only meaningful in its water");
  e.salinity_psu = optionalNumber(w, "salinity_psu").value_or(35.0);
  e.depth_m = optionalNumber(w, "depth_m").value_or(0.0);
  if (e.depth_m < 0.0) e.depth_m = 0.0;  // a log mean just above the surface
  e.water.pressure_dbar = optionalNumber(w, "pressure_dbar").value_or(seawater::pressureFromDepth(e.depth_m));
  if (e.water.pressure_dbar < 0.0) e.water.pressure_dbar = 0.0;
  e.water.density_kgm3 = optionalNumber(w, "density_kgm3")
                             .value_or(seawater::density(e.salinity_psu, e.water.temperature_degC, e.water.pressure_dbar));
  if (!(e.water.density_kgm3 > 900.0 && e.water.density_kgm3 < 1100.0)) {
    w.fail("density_kgm3", "not a seawater density", "expected 900-1100 kg/m3 in situ");
  }
  if (root.has("errors") && root.node()["errors"].is_object()) {
    const JsonReader er = root.child("errors");
    e.depth_error_m = optionalNumber(er, "depth_m");
    e.pitch_error_deg = optionalNumber(er, "pitch_deg");
    e.roll_deg = optionalNumber(er, "roll_deg");
  }
  if (report.contains("details") && report["details"].is_object() && report["details"].contains("auv_estimate")) {
    const nlohmann::json& d = report["details"]["auv_estimate"];
    if (d.is_object() && d.contains("calibrated_hydrodynamics") && d["calibrated_hydrodynamics"].is_object())
      e.calibrated_hydrodynamics = d["calibrated_hydrodynamics"];
    if (d.is_object() && d.contains("bg_mm") && d["bg_mm"].is_number() && d.value("bg_source", "profile") != "profile") {
      const double bg_mm = d["bg_mm"].get<double>();
      if (!(bg_mm > 0.0 && bg_mm < 500.0))
        JsonReader(d, file, "details.auv_estimate").fail("bg_mm", "BG must be above 0 and below 500 mm", "give the roll test's BG in mm");
      e.bg_m = units::mmToM(bg_mm);
    }
    if (d.is_object() && d.contains("calibration_manoeuvre") && d["calibration_manoeuvre"].is_object())
      e.calibration_manoeuvre = d["calibration_manoeuvre"];
    if (d.is_object() && d.contains("after_move_expected_sigma") && d["after_move_expected_sigma"].is_object()) {
      const nlohmann::json& a = d["after_move_expected_sigma"];
      if (a.contains("net_buoyancy_kg") && a["net_buoyancy_kg"].is_number())
        e.after_move_net_sigma_kg = a["net_buoyancy_kg"].get<double>();
      if (a.contains("cg_x_mm") && a["cg_x_mm"].is_number()) e.after_move_x_sigma_m = a["cg_x_mm"].get<double>() * 1e-3;
    }
  }
  if (report.contains("calibration") && report["calibration"].is_array())
    for (std::size_t i = 0; i < report["calibration"].size(); ++i) {
      const nlohmann::json& c = report["calibration"][i];
      if (!c.is_object() || !c.value("used", false) || !c.contains("value") || !c["value"].is_number()) continue;
      const std::string id = c.value("id", std::string());
      if (id != "hull_compressibility" && id != "thermal_expansion") continue;
      // A used law widens the plan's margin by its sigma: a missing or
      // negative one would narrow the margin without a word.
      const JsonReader entry(c, file, "calibration[" + std::to_string(i) + "]");
      const double sigma = requiredNumber(entry, "sigma", "a used buoyancy law needs its 1-sigma");
      if (!(sigma >= 0.0)) entry.fail("sigma", "must be >= 0", "write the law's 1-sigma in its unit");
      if (id == "hull_compressibility") {
        e.hull_compressibility_per_dbar = c["value"].get<double>();
        e.hull_compressibility_sigma_per_dbar = sigma;
      }
      if (id == "thermal_expansion") {
        e.hull_thermal_expansion_per_degC = c["value"].get<double>();
        e.hull_thermal_expansion_sigma_per_degC = sigma;
      }
    }
  if (report.contains("details") && report["details"].is_object() && report["details"].contains("flight_envelope")) {
    const nlohmann::json& f = report["details"]["flight_envelope"];
    if (f.is_object()) {
      e.log_too_light = f.contains("too_light");
      e.log_too_heavy = f.contains("too_heavy");
      e.log_porpoising = f.contains("porpoising");
    }
  }
  return e;
}

}  // namespace auv
