#include "planning/plan_sources.h"

#include <cmath>

#include "common/input_error.h"
#include "planning/report_consistency.h"
#include "history/ballasting_file.h"  // the deviation keys a ballasting-file record carries (header only)
#include "seawater/seawater.h"

namespace auv {
namespace {

std::optional<double> number(const nlohmann::json& j, const char* k) {
  if (j.is_object() && j.contains(k) && j[k].is_number()) return j[k].get<double>();
  return std::nullopt;
}

// Deviations only: the thesis balances the recorded total weight against
// rho V at the surface of the last measured water (eq. 5.2).
TrimEstimate deviationsOnlyEstimate(const VehicleProfile& v, const nlohmann::json& r,
                                    std::optional<double> total_mass_kg, std::optional<MeasuredWater> measured,
                                    double& imbalance_kg) {
  TrimEstimate e;
  const nlohmann::json errors = r.contains("errors") && r["errors"].is_object() ? r["errors"] : nlohmann::json::object();
  e.depth_error_m = number(errors, "depth_m") ? number(errors, "depth_m") : number(r, kDepthDeviationKey);
  e.pitch_error_deg = number(errors, "pitch_deg") ? number(errors, "pitch_deg") : number(r, kPitchDeviationKey);
  e.roll_deg = number(errors, "roll_deg") ? number(errors, "roll_deg") : number(r, kRollDeviationKey);
  if (!measured) {
    throw InputError("water", "no measured water for this configuration to turn the weight into a balance",
                     "give an analysis report with water, or import the ballasting file with its temperature");
  }
  if (!total_mass_kg) {
    throw InputError("installed", "no recorded total weight to compare with the buoyancy (thesis eq. 5.2)",
                     "give an analysis report with net_buoyancy_kg");
  }
  e.water.temperature_degC = measured->temperature_degC;
  e.salinity_psu = measured->salinity_psu;
  e.depth_m = 0.0;
  e.water.pressure_dbar = 0.0;
  e.water.density_kgm3 = seawater::density(e.salinity_psu, e.water.temperature_degC, 0.0);
  imbalance_kg = e.water.density_kgm3 * v.hull.volumeAt(e.water.temperature_degC, 0.0) - *total_mass_kg;
  e.net_buoyancy_kg = imbalance_kg;
  return e;
}

}  // namespace

PlanStart planStartFromReport(const VehicleProfile& v, const nlohmann::json& report, const std::string& report_name,
                              PlanPolicy policy, std::optional<double> recorded_total_mass_kg,
                              std::optional<MeasuredWater> measured) {
  // Another vehicle's estimate would give a plausible but meaningless move
  // (CLI and wizard both start here).
  checkReportMatchesVehicle(report, report_name, v);
  PlanStart s;
  s.physical = number(report, "net_buoyancy_kg").has_value();
  if (s.physical) {
    s.estimate = trimEstimateFromReport(report, report_name);
    if (policy == PlanPolicy::Classic && recorded_total_mass_kg) {
      // The thesis's own balance (eq. 5.2): recorded weight against rho V.
      const WaterState& w = s.estimate.water;
      s.classic_computed_imbalance_kg =
          w.density_kgm3 * v.hull.volumeAt(w.temperature_degC, w.pressure_dbar) - *recorded_total_mass_kg;
    }
    return s;
  }
  if (policy != PlanPolicy::Classic) {
    // An analysis says why it could not tell; a report without it (e.g.
    // deviations imported from a thesis ballasting file) never had one.
    const auto ni = report.find("not_identifiable");
    if (ni != report.end() && ni->is_object() && ni->contains("net_buoyancy_kg") &&
        (*ni)["net_buoyancy_kg"].is_string()) {
      throw InputError("report.net_buoyancy_kg",
                       report_name + ": the net buoyancy is " + (*ni)["net_buoyancy_kg"].get<std::string>(),
                       "plan from the model check's estimate of the same log, or use the classic policy");
    }
    throw InputError("report.net_buoyancy_kg",
                     report_name + " has no net buoyancy (e.g. deviations imported from a thesis ballasting file)",
                     "use the classic policy, or analyse the mission log ('auvballast analyze') and plan from that "
                     "report");
  }
  s.estimate = deviationsOnlyEstimate(v, report, recorded_total_mass_kg, measured, s.classic_computed_imbalance_kg);
  return s;
}

PlannedWater lastMissionWater(const TrimEstimate& e, double latitude_deg) {
  PlannedWater w;
  w.temperature_degC = e.water.temperature_degC;
  w.salinity_psu = e.salinity_psu;
  w.depth_m = e.depth_m;
  w.latitude_deg = latitude_deg;
  return w;
}

std::vector<double> installedAfterPlan(const std::vector<double>& installed_kg, const PreMissionPlan& plan) {
  std::vector<double> out;
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const double before = i < installed_kg.size() ? installed_kg[i] : 0.0;
    out.push_back(std::round((before + plan.points[i].add_kg) * 1e4) / 1e4);
  }
  return out;
}

}  // namespace auv
