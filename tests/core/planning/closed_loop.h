#pragma once
// Closed-loop check of the pre-mission policies: a known "true" vehicle
// flies a mission, an analysis estimates it, a policy plans the move, the
// move is applied to the truth, and the next mission is judged against the
// thesis's spec (§5.1 item 7). Truth here is analytic: exact hydrostatics
// for net buoyancy and the attitude at rest (what the solver predicts and
// the spec bands are about); the 'analysis' step is the truth plus Gaussian errors at the sigma the
// post-mission analysis states for HUGIN (see
// docs/decisions/planning-closed-loop.md). Shared by the planning test and
// bench/policy_compare.
#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "planning/pre_mission_plan.h"
#include "vehicle/vehicle_profile.h"

namespace auv::closed_loop {

// How the analysis's 1-sigma grows with what it measures (a + b |value|),
// and how large the realised error is relative to that sigma.
struct AnalysisNoise {
  double net_a_kg = 0.25, net_b = 0.085;
  double x_a_mm = 0.50, x_b = 0.060;
  double y_a_mm = 0.004, y_b = 0.001;
  double realised = 1.0;  // error ~ N(0, realised * sigma)
  double roll_sensor_sigma_deg = 0.02;  // for the classic table's readings
  double pitch_sensor_sigma_deg = 0.05;
  double depth_sensor_sigma_m = 0.01;
  // How well the operator knows the next mission's water (a CTD cast before launch).
  double next_temperature_sigma_degC = 0.1, next_salinity_sigma_psu = 0.05;
};

struct LoopCase {
  double light_kg = 0.0;           // truth: B - W in mission 1's operating water
  double x_mm = 0.0, y_mm = 0.0;   // truth: CG - CB
  PlannedWater water1, water2;     // operating water of this and the next mission
  std::vector<double> installed_kg;  // pieces at the points before the plan (profile order)
  std::uint64_t seed = 0;
};

// The ranges: 1-8 kg light, |x| 5-25 mm, |y| 0.5-3 mm (random signs),
// 4-14 degC, 33-35.5 PSU, 20-100 m, installed 9.6-24 kg per point.
std::vector<LoopCase> makeCases(const VehicleProfile& v, int count, std::uint64_t seed);

struct Truth {
  double mass_kg = 0.0;
  Eigen::Vector3d cg_m = Eigen::Vector3d::Zero();
  std::vector<double> installed_kg;
};

struct MissionResult {
  double net_kg = 0.0;              // at the operating point
  double min_net_kg = 0.0;          // over operating point and surface
  double static_pitch_deg = 0.0, static_roll_deg = 0.0;
  double depth_error_m = 0.0;       // commanded - measured, see decision note
};

struct SpecCheck {
  bool net = false, pitch = false, depth = false, roll = false;
  bool all() const { return net && pitch && depth && roll; }
};

struct Outcome {
  MissionResult before, after;
  SpecCheck spec;
  bool safe = false;                // true net >= 0 at every planned point
  double best_roll_deg = 0.0;       // what the kit allows (exact plan on the truth itself)
  double best_pitch_deg = 0.0;
  bool reachable = false;           // that perfect-knowledge plan meets the pitch band
  double added_kg = 0.0;
  std::vector<std::string> warnings;
};

class Harness {
 public:
  explicit Harness(VehicleProfile v, AnalysisNoise noise = {});

  Truth truthOf(const LoopCase& c) const;
  MissionResult fly(const Truth& t, const PlannedWater& w) const;
  TrimEstimate analyse(const Truth& t, const PlannedWater& w, std::mt19937_64& rng) const;
  SpecCheck judge(const MissionResult& m, double best_roll_deg) const;

  // mission 1 -> analyse -> plan -> apply -> mission 2.
  Outcome runOnce(const LoopCase& c, PlanPolicy policy, bool optional_pieces, double sigma_factor = 1.645) const;
  // Missions the classic table needs until the spec holds (0 = already), or
  // nullopt if it does not within max_missions.
  std::optional<int> classicMissions(const LoopCase& c, int max_missions) const;

  const VehicleProfile& vehicle() const { return v_; }
  // Attitude after the exact plan made with perfect knowledge of the truth:
  // what the kit, the capacities and the installed pieces allow at best.
  struct Best {
    double pitch_deg = 0.0, roll_deg = 0.0;
  };
  Best best(const Truth& t, const PlannedWater& w, bool optional_pieces) const;
  // The exact plan made with perfect knowledge of the truth in that water.
  PreMissionPlan perfectPlan(const Truth& t, const PlannedWater& w, bool optional_pieces) const;
  void apply(Truth& t, const PreMissionPlan& p) const;

 private:
  VehicleProfile v_;
  AnalysisNoise noise_;
};

}  // namespace auv::closed_loop
