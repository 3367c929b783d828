#include "planning/report_consistency.h"

#include <algorithm>

#include "common/input_error.h"
#include "vehicle/json_reader.h"

namespace auv {
namespace {

constexpr std::string_view kReportDoc = "docs/formats/analysis-report.md";

std::string pointNames(const VehicleProfile& v) {
  std::string s;
  for (const auto& p : v.points) s += (s.empty() ? "" : ", ") + p.name;
  return s;
}

void refuseIfObject(const JsonReader& root, const std::string& key, std::initializer_list<std::string_view> known) {
  if (root.node().is_object() && root.node().contains(key) && root.node()[key].is_object()) {
    root.child(key).refuseUnknownKeys(known, kReportDoc);
  }
}

}  // namespace

void checkReportMatchesVehicle(const nlohmann::json& report, const std::string& report_name, const VehicleProfile& v) {
  if (!report.is_object()) return;
  const std::string fix = "plan with --vehicle of the analysed vehicle, or analyse this vehicle's own log";
  if (report.contains("vehicle") && report["vehicle"].is_string() && report["vehicle"] != v.id) {
    throw InputError("vehicle",
                     "the report analyses vehicle '" + report["vehicle"].get<std::string>() + "', not '" + v.id + "'",
                     fix, {report_name, 0, 0});
  }
  if (report.contains("vehicle_kind") && report["vehicle_kind"].is_string() && report["vehicle_kind"] != v.kind) {
    throw InputError("vehicle_kind",
                     "the report is for a " + report["vehicle_kind"].get<std::string>() + ", vehicle '" + v.id +
                         "' is a " + v.kind,
                     fix, {report_name, 0, 0});
  }
  if (report.contains("recommendation") && report["recommendation"].is_object() &&
      report["recommendation"].contains("points") && report["recommendation"]["points"].is_array()) {
    const auto& pts = report["recommendation"]["points"];
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (!pts[i].is_object() || !pts[i].contains("name") || !pts[i]["name"].is_string()) continue;
      const std::string name = pts[i]["name"].get<std::string>();
      if (!v.findPoint(name)) {
        throw InputError("recommendation.points[" + std::to_string(i) + "].name",
                         "point '" + name + "' is not an adjustment point of '" + v.id + "' (" + pointNames(v) + ")",
                         fix, {report_name, 0, 0});
      }
    }
  }
}

void refuseUnknownReportKeys(const nlohmann::json& report, const std::string& report_name) {
  const JsonReader root(report, report_name);
  root.refuseUnknownKeys(
      {"vehicle", "vehicle_kind", "log", "rows", "duration_s", "net_buoyancy_kg", "net_buoyancy_sigma_kg", "cg_offset_mm",
       "cg_offset_sigma_mm", "cg_offset_y_basis", "cruise", "mass_to_add_g", "mass_to_add_sigma_g", "target_density_kgm3",
       "errors", "errors_ci95", "pitch_error_basis", "pitch_at_steady_depth_deg", "water", "water_ci95", "water_sources",
       "segments", "not_identifiable", "warnings", "notes", "details", "recommendation", "recommendation_unavailable",
       "missing_physics", "model_check", "slope", "calibration", "calibration_findings"},
      kReportDoc);
  refuseIfObject(root, "cg_offset_mm", {"x", "y"});
  refuseIfObject(root, "cg_offset_sigma_mm", {"x", "y"});
  refuseIfObject(root, "cruise", {"prop_rpm", "speed_mps", "roll_deg", "roll_sigma_deg", "cg_y_mm", "cg_y_sigma_mm", "trimmed"});
  if (root.has("cruise") && root.node()["cruise"].is_object())
    refuseIfObject(root.child("cruise"), "trimmed", {"speed_mps", "torque_change_nm", "cg_y_shift_mm"});
  refuseIfObject(root, "errors", {"depth_m", "pitch_deg", "roll_deg"});
  refuseIfObject(root, "water", {"temperature_degC", "salinity_psu", "density_kgm3", "pressure_dbar", "depth_m"});
}

}  // namespace auv
