#pragma once
// Everything the operator has entered so far and the last computed report.
// Pages read and write this one object, so going back and forth loses nothing
// and the whole session can be autosaved and resumed (session_json.h).
#include <memory>
#include <optional>
#include <string>

#include "analysis/analysis_report.h"
#include "discrepancy/model_check.h"
#include "discrepancy/vehicle_check.h"
#include "firstmission/first_mission_report.h"
#include "firstmission/hugin_first_mission.h"
#include "missionlog/mission_log.h"
#include "missionlog/read_report.h"
#include "planning/pre_mission_plan.h"
#include "vehicle/vehicle_profile.h"
#include "weighing/tank_weighing.h"

namespace auv::ui {

// The thesis sequence: weigh before the first mission, analyse a recorded
// mission afterwards, plan the next one.
enum class SessionMode { kFirstMission, kPostMission, kPreMission };

// The pitch sensor level check's range, deg (the CLI's
// --pitch-alignment-sigma-deg takes 0..5; the wizard's 0 is "not checked").
inline constexpr double kMinPitchAlignmentDeg = 0.01;
inline constexpr double kMaxPitchAlignmentDeg = 5.0;

struct WizardState {
  std::string resource_dir;
  std::string vehicles_dir;
  std::optional<VehicleProfile> vehicle;

  // The configuration (thesis §5.5.1) being ballasted.
  std::string configuration_id;
  std::string payload_note;
  std::string area;
  std::string water_type;
  bool configuration_in_history = false;  // picked on the start page, not new
  // BG (CG below CB, mm) from an inclining or roll test: with it the analysis
  // identifies CG y and roll from the log; unset = not measured. Stored with
  // the configuration in the history.
  std::optional<double> bg_mm;

  SessionMode mode = SessionMode::kFirstMission;

  // First mission, crane method (HUGIN class): weighing, installed, water, policy.
  CraneFirstMissionInput crane;
  // First mission, Slocum tank method: readings, ballast, roll test.
  TankWeighing tank;
  bool tank_water_salt = false;  // the fresh/salt choice; sets the density range

  // Post mission: the imported log and what the reader said about it.
  std::string log_file;
  std::shared_ptr<const MissionLog> log;
  std::optional<ReadReport> log_report;
  std::string log_format;

  // Post mission: core/analysis on the imported log (installed pieces during
  // that mission, profile order), and the model check with the terms the
  // technician accepted (names of MissingPhysics entries).
  std::vector<double> mission_installed_kg;
  // AUVs: the pitch sensor's alignment from a level check on the dock, 1
  // sigma in deg (AnalysisOptions::pitch_alignment_sigma_deg); unset = not
  // checked, the analysis's 1 deg prior.
  std::optional<double> pitch_alignment_sigma_deg;
  std::optional<analysis::AnalysisReport> analysis;
  std::optional<discrepancy::ModelCheckResult> model_check;
  std::vector<std::string> accepted_terms;
  // The check model the result belongs to (gliders: the joint mass to add
  // for another target water is computed from it; not saved).
  std::shared_ptr<const discrepancy::CheckModel> check_model;
  // The configuration's vehicle model: the profile JSON with the terms
  // accepted so far (discrepancy/profile_update.h). `history_model` is what
  // the history had when the configuration was picked; `model_profile` adds
  // this session's accepted terms. Null = the catalog's profile.
  nlohmann::json history_model, model_profile;

  // Pre mission: the next mission's water and policy, the plan, what the
  // technician ticked off and what was actually installed (saved to history).
  std::optional<PlannedWater> next_water;
  double next_deepest_m = 0.0;                       // deepest planned point; <= operating depth: none
  std::string next_water_source = "last mission";  // or "operator" (the values entered)
  PlanPolicy policy = PlanPolicy::Exact;
  std::optional<PreMissionPlan> plan;
  std::vector<bool> checklist_done;
  std::vector<double> actually_installed_kg;

  // Gliders, pre mission: the answer for the chosen target water
  // (planGliderBallast JSON: grams per bottle, or lead and C_VBD), null until
  // the glider pre-mission page has one.
  nlohmann::json glider_plan;

  std::optional<FirstMissionReport> report;
  std::string last_error;

  bool isGlider() const { return vehicle && vehicle->kind == "glider"; }
};

}  // namespace auv::ui
