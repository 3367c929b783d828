#include "planning/recommend_from_analysis.h"

#include "common/input_error.h"
#include "planning/glider_ballast_plan.h"
#include "planning/pre_mission_plan.h"

namespace auv {

nlohmann::json recommendFromAnalysis(const VehicleProfile& vehicle, const nlohmann::json& analysis_json,
                                     const std::vector<double>& installed_kg, std::string& why_not) {
  if (vehicle.kind == "glider") {
    // Gliders: grams per bottle (or lead and C_VBD) for the report's target.
    if (!analysis_json.contains("mass_to_add_g") || !analysis_json["mass_to_add_g"].is_number()) {
      why_not = "the log did not identify the glider's net buoyancy";
      return nullptr;
    }
    try {
      return planGliderBallast(vehicle, {analysis_json, installed_kg, std::nullopt});
    } catch (const InputError& e) {
      why_not = e.what();
      return nullptr;
    }
  }
  if (vehicle.points.empty() || vehicle.kit.pieces_kg.empty()) {
    why_not = "the profile has no adjustment points with a weight kit";
    return nullptr;
  }
  if (!analysis_json.contains("net_buoyancy_kg") || analysis_json["net_buoyancy_kg"].is_null()) {
    why_not = "the log did not identify the net buoyancy";
    return nullptr;
  }
  try {
    PreMissionInput in;
    in.installed_kg = installed_kg.empty() ? std::vector<double>(vehicle.points.size(), 0.0) : installed_kg;
    in.estimate = trimEstimateFromReport(analysis_json, "analysis");
    const PlannedWater same{in.estimate.water.temperature_degC, in.estimate.salinity_psu, in.estimate.depth_m, 45.0};
    in.next = nextMissionWater(same, in.estimate.depth_m, "last mission");
    const nlohmann::json plan = toJson(planPreMission(vehicle, in));
    nlohmann::json rec = plan.value("recommendation", nlohmann::json::object());
    if (!rec.contains("predicted") && plan.contains("predicted")) rec["predicted"] = plan["predicted"];
    if (plan.contains("warnings")) rec["warnings"] = plan["warnings"];
    return rec;
  } catch (const InputError& e) {
    why_not = e.what();
    return nullptr;
  }
}

}  // namespace auv
