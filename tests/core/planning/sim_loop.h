#pragma once
// The closed loop with the simulator as truth and the real post-mission
// analysis in between: HUGIN flies three level legs (160, 120, 140 rpm, as in
// resources/examples/hugin1000_ballast_error.plan.json) with the installed
// pieces and a ballast error, the log goes through core/analysis and its JSON
// report, the plan's move is added to the installed pieces, and the next
// mission is flown and judged. Truth after the move comes from the log's
// metadata (what the simulator flew); depth error, pitch and roll are judged
// as the thesis measures them in flight (§5.3): the analysis's depth error,
// pitch at steady depth and roll at cruise rpm of the next mission.
#include <optional>
#include <string>
#include <vector>

#include "analysis/mission_analysis.h"
#include "closed_loop.h"
#include "planning/pre_mission_plan.h"
#include "sim/flown_mass.h"
#include "sim/mission_plan.h"

namespace auv::closed_loop {

struct SimLoopCase {
  // Truth in mission 1: B - W at its operating water, CG - CB (the simulator's
  // ballast error is derived from these and the installed pieces).
  double light_kg = 0.0, x_mm = 0.0, y_mm = 0.0;
  PlannedWater water1, water2;
  std::vector<double> installed_kg;
  std::uint64_t seed = 1;
};

// Same ranges as makeCases, installed 7.2, 7.2, 25.2, 25.2 kg (about neutral
// as believed, like the example plan), operating depth 30-100 m.
std::vector<SimLoopCase> makeSimCases(int count, std::uint64_t seed);

struct SimMission {
  double net_kg = 0.0;           // truth, mean over the logged samples
  double pitch_deg = 0.0, roll_deg = 0.0;  // truth, static attitude in that water
  double flight_pitch_deg = 0.0;  // the analysis's pitch at steady depth (thesis §5.3.2, depth check)
  double cruise_roll_deg = 0.0;   // the analysis's roll at cruise rpm (thesis §5.3.3)
  double cruise_pitch_deg = 0.0;  // mean pitch of the analysis's steady segments at cruise rpm
  double depth_error_m = 0.0, depth_error_ci95_m = 0.0;  // the analysis's, commanded - measured
  nlohmann::json report;         // the analysis's JSON report
  analysis::HistoryMission as_history;  // its steady segments and pieces, for a later joint calibration
  Truth truth;
};

struct SimOutcome {
  SimMission before, after;
  SpecCheck spec;
  bool safe = false;
  double best_roll_deg = 0.0, best_pitch_deg = 0.0;  // in flight after the perfect-knowledge plan
  bool reachable = false;      // that plan meets the static pitch band (for the record)
  double predicted_net_kg = 0.0, predicted_pitch_deg = 0.0, predicted_roll_deg = 0.0;
  std::optional<double> predicted_flight_pitch_deg;  // the plan's, at the last mission's cruise speed
  std::vector<std::string> warnings;  // the plan's
};

// Sigmas the plan uses instead of the analysis's own (nullopt = the
// analysis's): to separate the planner from the analysis's calibration.
struct SigmaOverride {
  std::optional<double> net_kg, x_mm, y_mm;
};

class SimHarness {
 public:
  // coefficient_rel_sigma: what the analysis states about the profile's
  // hydrodynamic derivatives (10 % by default; here the simulator flies
  // exactly those derivatives, so a smaller value is the calibrated case).
  explicit SimHarness(SigmaOverride sigma = {}, double coefficient_rel_sigma = 0.10);
  // history: earlier missions of this vehicle, calibrated jointly (issue 11 item 3).
  SimMission fly(const SimLoopCase& c, const std::vector<double>& installed_kg, const PlannedWater& w,
                 std::uint64_t seed, const std::vector<analysis::HistoryMission>& history = {}) const;
  // The simulator's ballast error that makes mission 1 the case's truth.
  sim::BallastError errorOf(const SimLoopCase& c) const;
  SimOutcome runOnce(const SimLoopCase& c, PlanPolicy policy, bool optional_pieces) const;
  // Exact policy twice (mission 1 -> move -> mission 2 -> move -> mission 3,
  // judged); `before` is mission 1, `after` mission 3.
  SimOutcome runTwice(const SimLoopCase& c, bool optional_pieces) const;
  std::optional<int> classicMissions(const SimLoopCase& c, int max_missions) const;
  const VehicleProfile& vehicle() const { return profile_; }

 private:
  PreMissionPlan plan(const SimMission& m, const std::vector<double>& installed, const PlannedWater& next,
                      PlanPolicy policy, bool optional_pieces) const;
  static std::vector<double> applied(const std::vector<double>& installed, const PreMissionPlan& p);
  SpecCheck judge(const SimMission& m, const SimMission& best) const;
  SimMission flyBest(const SimLoopCase& c, const SimMission& m, const PlannedWater& w, bool optional_pieces) const;
  VehicleProfile profile_;  // with the simulator's hydrodynamics as sections, for the analysis
  sim::SimVehicle sim_;
  sim::MissionPlan plan_;   // legs, noise and trace rate of the example plan
  Harness analytic_;
  SigmaOverride sigma_;
  double coefficient_rel_sigma_ = 0.10;
};

}  // namespace auv::closed_loop
