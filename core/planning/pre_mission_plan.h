#pragma once
// Pre-mission mode (thesis §5.4.2, done physically): from what the last
// mission showed (net buoyancy and CG offset with uncertainties, in the log's
// water), the pieces installed now and the next mission's water, which
// pieces to add or remove where, and what the vehicle will do after it.
//
// Safety rule (docs/decisions/planning-safety-margin.md): after the move the
// predicted net buoyancy must be at least
//     margin = k * sigma_net,   k = 1.645 (one-sided 95 %),
//     sigma_net^2 = sigma_estimate^2 + sigma_water^2,
// at EVERY planned point (operating depth, surface, deepest point), with the
// hull's compressibility and thermal expansion. The acceptance band applies
// at the operating point; the solver is asked for
//     [max(spec min, margin + B_operating - min_i B_i),  spec max - margin]
// (the upper margin only keeps the true value in band; it yields to the
// lower edge). If no kit total lies in that band the plan stays safe and
// ends lighter, and says so.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ballast/ballast_problem.h"
#include "common/message.h"
#include "firstmission/first_mission_report.h"
#include "planning/classic_table.h"
#include "planning/estimated_vehicle.h"
#include "planning/next_mission_water.h"
#include "planning/trim_estimate.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

enum class PlanPolicy { Exact, HalfWay, Classic };
const char* toString(PlanPolicy p);                // "exact", "half", "classic"
PlanPolicy planPolicyFromString(const std::string& s);  // InputError("policy") if unknown

struct PreMissionInput {
  std::vector<double> installed_kg;  // adjustment mass at each profile point now, profile order
  TrimEstimate estimate;
  NextMissionWater next;
  PlanPolicy policy = PlanPolicy::Exact;
  bool use_optional_pieces = false;  // e.g. HUGIN's 0.5 kg piece (thesis §8.1)
  double sigma_factor = 1.645;       // k of the safety margin
  std::optional<HullModel> hull;     // accepted model terms; default: the profile's hull
  // Classic only: B - W the thesis computes from the recorded total weight
  // and the water (eq. 5.2), + = light.
  double classic_computed_imbalance_kg = 0.0;
};

struct PlannedPointResult {
  std::string role;  // "operating", "surface", "deepest", "transit"
  PlannedWater water;
  WaterState state;
  double displaced_kg = 0.0;
  double net_before_kg = 0.0, net_after_kg = 0.0;
};

struct PreMissionPlan {
  std::string vehicle_id;
  PlanPolicy policy = PlanPolicy::Exact;
  EstimatedVehicle vehicle;     // mass and CG as the last mission showed them
  TrimEstimate estimate;
  std::vector<double> piece_sizes_kg;
  std::vector<std::vector<int>> delta;  // [point][size], signed
  std::vector<PointRecommendation> points;
  double net_before_kg = 0.0, pitch_before_deg = 0.0, roll_before_deg = 0.0;  // at the operating point
  PredictedTrim predicted;      // at the operating point
  double net_sigma_kg = 0.0, pitch_sigma_deg = 0.0, roll_sigma_deg = 0.0;
  double hull_law_sigma_kg = 0.0;  // the fitted hull law's share of net_sigma_kg (0: the profile's law)
  // Pitch in level flight at the last mission's cruise speed (thesis §5.3.2
  // judges it there), before and after the move; unset without the
  // profile's hydrodynamics or a cruise speed (analysis/level_flight.h).
  std::optional<double> flight_pitch_before_deg, flight_pitch_after_deg;
  double flight_speed_mps = 0.0;
  std::optional<bool> flight_pitch_in_band;  // the spec's pitch band, judged in flight
  double margin_kg = 0.0;       // k * sigma_net
  double band_lo_kg = 0.0, band_hi_kg = 0.0;  // net buoyancy band asked of the solver at the operating point
  std::vector<PlannedPointResult> at_points;  // operating first
  bool safe = false;            // net after >= margin at every point
  bool buoyancy_in_band = false, pitch_in_band = false, roll_in_band = false;
  std::vector<Message> explanations;  // one sentence per changed point (common/message.h)
  // When the estimate's sigma is too wide for the spec band (the margin
  // pushes the vehicle out of it): the short addition to the next mission
  // that would identify the rest {legs, expected_sigma} (issue 11 item 5).
  std::optional<nlohmann::json> calibration_manoeuvre;
  // With the same condition: this move is itself a calibration; the sigmas
  // the next mission's survey, analysed with the last log as history, should
  // reach (the analysis's prediction).
  std::optional<double> after_move_net_sigma_kg, after_move_x_sigma_m;
  std::vector<Message> notes, warnings;
  nlohmann::json details = nlohmann::json::object();
};

PreMissionPlan planPreMission(const VehicleProfile& vehicle, const PreMissionInput& input);

// JSON contract: recommendation {policy, points [{name, label, add_kg,
// pieces [{size_kg, count}], explanation}], predicted {...}}, predicted
// (same shape as the first-mission report, plus sigmas), before, safety,
// water {log, operating, points}, estimate, warnings, notes.
nlohmann::json toJson(const PreMissionPlan& p);
std::string toText(const PreMissionPlan& p);

}  // namespace auv
