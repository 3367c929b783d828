#pragma once
// Where the pre-mission pages get what core/planning needs: the estimate
// (this session's analysis, else the history's latest), the pieces installed
// now, the next mission's water and policy from the state. Only gathering
// and mapping here; every number comes from core (planning/plan_sources.h).
#include <optional>
#include <string>
#include <vector>

#include "discrepancy/plan_estimate.h"
#include "history/records.h"
#include "planning/installed_prediction.h"
#include "planning/plan_sources.h"
#include "wizard/wizard_state.h"

namespace auv {
class HistoryStore;
}

namespace auv::ui {

// What the plan starts from, and where that came from (for the screen and
// the records).
struct PlanBasis {
  PlanStart start;
  bool from_session = false;              // this session's analysis, else the history's
  std::string analysis_name;              // "this session's analysis of X" / "history analysis #N"
  std::optional<RecordId> analysis_id;    // the history record, if the estimate is one
  std::optional<TimePoint> measured_at;   // when the estimate's water was measured, if known
  std::vector<double> installed_kg;       // now, profile order
  std::string installed_source;           // "as flown in the analysed mission", "history YYYY-MM-DD", ...
  std::optional<double> total_mass_kg;    // recorded vehicle mass with those pieces
  // Which estimate (this log's analysis, or with the accepted model-check
  // terms) and the report it is, for its calibration list and manoeuvre.
  discrepancy::EstimateSource source = discrepancy::EstimateSource::kAnalysis;
  nlohmann::json report;
};

// The one estimate of this session (discrepancy/plan_estimate.h): the
// analysis, with the model check's ballast state once terms are accepted.
// Empty without an analysis.
std::optional<discrepancy::PlanEstimate> sessionEstimate(const WizardState& s);

// True when a plan can start: the session has an analysis, or the history
// has one for the configuration.
bool hasAnalysisToPlanFrom(const WizardState& s, HistoryStore* store, TimePoint now);

// Throws InputError (field named) when there is no analysis, the analysis
// cannot be planned from with `policy`, or no vehicle is chosen.
PlanBasis planBasis(const WizardState& s, HistoryStore* store, TimePoint now, PlanPolicy policy);

// Pieces installed now, profile order: those flown in this session's
// analysed mission, else the configuration's (crane input or, for a glider,
// the tank-weighing ballast items) as the start page took them from the history.
std::vector<double> installedNow(const WizardState& s);

// state.next_water / next_deepest_m / next_water_source as core's input.
NextMissionWater nextWaterOf(const WizardState& s);

// The input planPreMission gets from the state and the basis.
PreMissionInput preMissionInput(const WizardState& s, const PlanBasis& b);

// One line of the technician's checklist: add or remove `count` pieces of
// one size at one point (a changed (point, size) pair of the plan).
struct ChecklistStep {
  std::size_t point = 0;
  double size_kg = 0.0;
  int count = 0;  // signed: negative = remove
};
// Removals first (room at the point, and the vehicle never gets heavier on
// the way), then additions; profile order and largest piece first within each.
std::vector<ChecklistStep> checklistSteps(const PreMissionPlan& plan);

// Decimals that show every kit piece exactly (1.2 kg: 1; 0.05 kg: 2; 1 g: 3).
int massDecimals(const std::vector<double>& piece_sizes_kg);

// The exported JSON report: the plan (core toJson) plus configuration,
// sources, installed before / planned / actually installed and the
// prediction for what is actually installed.
nlohmann::json preMissionReportJson(const WizardState& s, const PlanBasis& b, const std::string& created_at);

}  // namespace auv::ui
