#pragma once
// What a pre-mission plan starts from, shared by `auvballast plan` and the
// GUI's pre-mission page so both turn the same records into the same
// PreMissionInput: the estimate from an analysis report (or, for the
// thesis's classic table, from the recorded total weight when the report has
// only deviations), the last mission's water as the default for the next
// one, and the installed masses after a plan.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "planning/pre_mission_plan.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

// The last measured water of the configuration (history), used when the
// report carries deviations but no physical estimate.
struct MeasuredWater {
  double temperature_degC = 0.0;
  double salinity_psu = 35.0;
};

struct PlanStart {
  TrimEstimate estimate;
  bool physical = true;  // the report has a net buoyancy; false = deviations only (classic table)
  // B - W by the thesis's own balance (eq. 5.2): recorded total weight
  // against rho V of the estimate's water; 0 when no total weight is known.
  double classic_computed_imbalance_kg = 0.0;
};

// `report` is an analysis report (issue #3 contract) or a history analysis
// record's result. A report without net_buoyancy_kg (e.g. deviations imported
// from a thesis ballasting file) can only feed the classic policy; then the
// mass comes from `recorded_total_mass_kg` and the water from `measured`
// (InputError naming "installed" / "water" when missing). Any other policy
// without a net buoyancy throws InputError("report.net_buoyancy_kg").
PlanStart planStartFromReport(const VehicleProfile& v, const nlohmann::json& report, const std::string& report_name,
                              PlanPolicy policy, std::optional<double> recorded_total_mass_kg,
                              std::optional<MeasuredWater> measured);

// The next mission in the last mission's water: the estimate's temperature,
// salinity and depth (its CTD at the operating depth).
PlannedWater lastMissionWater(const TrimEstimate& e, double latitude_deg = 45.0);

// Adjustment mass at each point after the plan's move, in whole 0.1 g like
// the pieces (9.6 + 1.2 is 10.8 kg, not 10.799999999999999).
std::vector<double> installedAfterPlan(const std::vector<double>& installed_kg, const PreMissionPlan& plan);

}  // namespace auv
