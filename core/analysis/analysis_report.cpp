#include "analysis/analysis_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/units.h"

namespace auv::analysis {

namespace {

// Files carry 1e-6 of the unit: sub-gram, sub-micrometre.
nlohmann::json num(double v) {
  if (!std::isfinite(v)) return nullptr;
  return std::round(v * 1e6) / 1e6;
}

// Six significant digits: calibrated constants span 1e-6 1/dbar (a hull's
// compressibility) to thousands, where six decimals would erase the small ones.
nlohmann::json sig6(double v) {
  if (!std::isfinite(v)) return nullptr;
  if (v == 0.0) return 0.0;
  const double k = std::pow(10.0, 5 - static_cast<int>(std::floor(std::log10(std::abs(v)))));
  return std::round(v * k) / k;
}

nlohmann::json ci(const MeanEstimate& m) { return m.valid() ? num(m.ci95) : nlohmann::json(nullptr); }

std::string fmt(const char* f, double v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The same format without the forced sign, for interval half-widths.
std::string fmtAbs(const char* f, double v) {
  std::string u = f;
  if (const auto k = u.find('+'); k != std::string::npos) u.erase(k, 1);
  return fmt(u.c_str(), v);
}

std::string pm(const MeanEstimate& m, const char* f, const char* unit) {
  if (!m.valid()) return "n/a";
  std::string s = fmt(f, m.mean);
  if (std::isfinite(m.ci95)) s += " +- " + fmtAbs(f, m.ci95);
  return s + " " + unit;
}

}  // namespace

const CalibrationParameter* calibrationParameter(const AnalysisReport& r, std::string_view id) {
  for (const CalibrationParameter& c : r.calibration)
    if (c.id == id) return &c;
  return nullptr;
}

nlohmann::json toJson(const AnalysisReport& r) {
  nlohmann::json j;
  j["vehicle"] = r.vehicle_id;
  j["vehicle_kind"] = r.vehicle_kind;
  j["log"] = r.log_name;
  j["rows"] = r.rows;
  j["duration_s"] = num(r.duration_s);
  j["net_buoyancy_kg"] = r.net_buoyancy_kg.known ? num(r.net_buoyancy_kg.value) : nullptr;
  j["net_buoyancy_sigma_kg"] = r.net_buoyancy_kg.known ? num(r.net_buoyancy_kg.sigma) : nullptr;
  j["cg_offset_mm"] = {{"x", r.cg_x_mm.known ? num(r.cg_x_mm.value) : nullptr},
                       {"y", r.cg_y_mm.known ? num(r.cg_y_mm.value) : nullptr}};
  j["cg_offset_sigma_mm"] = {{"x", r.cg_x_mm.known ? num(r.cg_x_mm.sigma) : nullptr},
                             {"y", r.cg_y_mm.known ? num(r.cg_y_mm.sigma) : nullptr}};
  if (!r.cg_y_basis.empty()) j["cg_offset_y_basis"] = r.cg_y_basis;
  if (r.cruise_roll_deg.known) {
    j["cruise"] = {{"prop_rpm", num(r.cruise_rpm)},
                   {"speed_mps", num(r.cruise_speed_mps)},
                   {"roll_deg", num(r.cruise_roll_deg.value)},
                   {"roll_sigma_deg", num(r.cruise_roll_deg.sigma)},
                   {"cg_y_mm", r.cruise_cg_y_mm.known ? num(r.cruise_cg_y_mm.value) : nullptr},
                   {"cg_y_sigma_mm", r.cruise_cg_y_mm.known ? num(r.cruise_cg_y_mm.sigma) : nullptr}};
    if (const auto& t = r.cruise_trimmed) {
      j["cruise"]["trimmed"] = {{"speed_mps", num(t->speed_mps)},
                                {"torque_change_nm", num(t->torque_change_nm)},
                                {"cg_y_shift_mm", num(units::mToMm(t->y_shift_m))}};
    }
  }
  if (r.vehicle_kind == "glider") {
    j["mass_to_add_g"] = r.mass_to_add_g.known ? num(r.mass_to_add_g.value) : nullptr;
    j["mass_to_add_sigma_g"] = r.mass_to_add_g.known ? num(r.mass_to_add_g.sigma) : nullptr;
    j["target_density_kgm3"] = num(r.target_density_kgm3);
    if (std::isfinite(r.target_density_kgm3))
      j["target"] = {{"density_kgm3", num(r.target_density_kgm3)},
                     {"pressure_dbar", num(r.target_pressure_dbar)},
                     {"temperature_degC", num(r.target_temperature_degC)},
                     {"basis", r.target_basis}};
  }
  j["errors"] = {{"depth_m", num(r.depth_error_m.mean)},
                 {"pitch_deg", num(r.pitch_error_deg.mean)},
                 {"roll_deg", num(r.roll_deg.mean)}};
  j["errors_ci95"] = {{"depth_m", ci(r.depth_error_m)}, {"pitch_deg", ci(r.pitch_error_deg)}, {"roll_deg", ci(r.roll_deg)}};
  j["pitch_error_basis"] = r.pitch_error_basis;
  j["pitch_at_steady_depth_deg"] = num(r.pitch_at_steady_depth_deg.mean);
  j["water"] = {{"temperature_degC", num(r.temperature_degC.mean)},
                {"salinity_psu", num(r.salinity_psu.mean)},
                {"density_kgm3", num(r.density_kgm3.mean)},
                {"pressure_dbar", num(r.pressure_dbar.mean)},
                {"depth_m", num(r.depth_m.mean)}};
  j["water_ci95"] = {{"temperature_degC", ci(r.temperature_degC)},
                     {"salinity_psu", ci(r.salinity_psu)},
                     {"density_kgm3", ci(r.density_kgm3)},
                     {"pressure_dbar", ci(r.pressure_dbar)},
                     {"depth_m", ci(r.depth_m)}};
  j["water_sources"] = {{"salinity", r.salinity_source}, {"density", r.density_source}};
  nlohmann::json segs = nlohmann::json::array();
  for (const SegmentReport& s : r.segments) {
    nlohmann::json g = {{"kind", toString(s.kind)}, {"start_s", num(s.start_s)}, {"end_s", num(s.end_s)}, {"used", s.used}};
    if (s.used) {
      g["depth_m"] = num(s.depth_m);
      g["depth_error_m"] = num(s.depth_error_m);
      g["pitch_deg"] = num(s.pitch_deg);
      g["pitch_error_deg"] = num(s.pitch_error_deg);
      g["roll_deg"] = num(s.roll_deg);
      g["speed_mps"] = num(s.speed_mps);
      g["prop_rpm"] = num(s.prop_rpm);
      g["elevator_deg"] = num(s.elevator_deg);
      if (std::isfinite(s.net_buoyancy_kg)) g["net_buoyancy_kg"] = num(s.net_buoyancy_kg);
      if (std::isfinite(s.cg_x_mm)) g["cg_x_mm"] = num(s.cg_x_mm);
      if (s.calibration_dropped) g["calibration_dropped"] = true;
    }
    segs.push_back(g);
  }
  j["segments"] = segs;
  nlohmann::json ni = nlohmann::json::object();
  if (!r.net_buoyancy_kg.known && !r.net_buoyancy_kg.why_not.empty()) ni["net_buoyancy_kg"] = r.net_buoyancy_kg.why_not;
  if (!r.cg_x_mm.known && !r.cg_x_mm.why_not.empty()) ni["cg_offset_mm.x"] = r.cg_x_mm.why_not;
  if (!r.cg_y_mm.known && !r.cg_y_mm.why_not.empty()) ni["cg_offset_mm.y"] = r.cg_y_mm.why_not;
  j["not_identifiable"] = ni;
  j["warnings"] = r.warnings;
  j["notes"] = r.notes;
  nlohmann::json cal = nlohmann::json::array();
  for (const CalibrationParameter& q : r.calibration) {
    cal.push_back({{"id", q.id}, {"value", sig6(q.value)}, {"unit", q.unit}, {"sigma", sig6(q.sigma)},
                   {"profile_value", sig6(q.profile_value)}, {"prior_sigma", sig6(q.prior_sigma)},
                   {"identified", q.identified}, {"used", q.used}});
    if (!q.rival.empty()) cal.back()["rival"] = q.rival;
  }
  j["calibration"] = cal;
  j["details"] = r.details;
  return j;
}

std::string toText(const AnalysisReport& r) {
  std::ostringstream o;
  o << "Post-mission analysis: " << r.vehicle_id << " (" << r.vehicle_kind << ")";
  if (!r.log_name.empty()) o << ", log " << r.log_name;
  o << "\n  " << r.rows << " rows, " << fmt("%.2f", r.duration_s / 3600.0) << " h\n";
  std::size_t used = 0, phases = 0;
  for (const auto& s : r.segments) (s.used ? used : phases)++;
  o << "  segments: " << phases << " phases, " << used << (r.vehicle_kind == "glider" ? " steady glides" : " steady level legs")
    << " used\n";
  o << "Water at operating depth (" << pm(r.depth_m, "%.1f", "m") << ", " << pm(r.pressure_dbar, "%.1f", "dbar") << "):\n";
  o << "  temperature " << pm(r.temperature_degC, "%.3f", "degC") << ", salinity " << pm(r.salinity_psu, "%.3f", "PSU")
    << ", in-situ density " << pm(r.density_kgm3, "%.3f", "kg/m3") << "\n";
  o << "Errors (95 % intervals):\n";
  o << "  depth (commanded - measured): " << pm(r.depth_error_m, "%+.3f", "m") << "\n";
  o << "  pitch: " << pm(r.pitch_error_deg, "%+.2f", "deg");
  if (!r.pitch_error_basis.empty()) o << "  [" << r.pitch_error_basis << "]";
  o << "\n  roll: " << pm(r.roll_deg, "%+.2f", "deg") << "\n";
  o << "Estimate:\n";
  auto est = [&](const char* name, const EstimatedValue& e, const char* f, const char* unit) {
    o << "  " << name << ": ";
    if (e.known) o << fmt(f, e.value) << " +- " << fmtAbs(f, e.sigma) << " " << unit << " (1 sigma)\n";
    else o << "n/a - " << e.why_not << "\n";
  };
  est("net buoyancy (positive = too light)", r.net_buoyancy_kg, "%+.3f", "kg");
  est("CG - CB x", r.cg_x_mm, "%+.1f", "mm");
  est("CG - CB y", r.cg_y_mm, "%+.1f", "mm");
  if (r.cg_y_mm.known && !r.cg_y_basis.empty()) o << "    (y basis: " << r.cg_y_basis << ")\n";
  if (r.cruise_roll_deg.known) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "  roll at cruise (%.0f rpm): %+.3f +- %.3f deg", r.cruise_rpm, r.cruise_roll_deg.value,
                  r.cruise_roll_deg.sigma);
    o << buf;
    if (r.cruise_cg_y_mm.known) {
      std::snprintf(buf, sizeof buf, "; levels at CG y %+.3f +- %.3f mm", r.cruise_cg_y_mm.value, r.cruise_cg_y_mm.sigma);
      o << buf;
    }
    o << "\n";
  }
  if (r.vehicle_kind == "glider") {
    if (r.mass_to_add_g.known)
      o << "  ballast to add for neutral (pump at zero) at " << fmt("%.2f", r.target_density_kgm3) << " kg/m3, "
        << fmt("%.0f", r.target_pressure_dbar) << " dbar, " << fmt("%.2f", r.target_temperature_degC) << " degC: "
        << fmt("%+.0f", r.mass_to_add_g.value) << " +- " << fmt("%.0f", r.mass_to_add_g.sigma) << " g\n"
        << "    target: " << r.target_basis << "\n";
  }
  if (r.details.contains("classic")) {
    const auto& c = r.details["classic"];
    o << "Classic (thesis App. D):";
    for (const char* k : {"depth_error_m", "pitch_error_deg", "pitch_at_stable_depth_deg", "roll_error_deg"}) {
      o << " " << k << "=";
      if (c[k].is_null() || c[k]["value"].is_null()) o << "n/a";
      else o << fmt("%+.3f", c[k]["value"].get<double>());
    }
    o << "\n";
  }
  for (const auto& w : r.warnings) o << "Warning: " << w << "\n";
  for (const auto& n : r.notes) o << "Note: " << n << "\n";
  return o.str();
}

}  // namespace auv::analysis
