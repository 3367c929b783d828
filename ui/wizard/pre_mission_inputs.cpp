#include "wizard/pre_mission_inputs.h"

#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "history/store.h"
#include "weighing/slocum_layout.h"
#include "workflow/plan_inputs_from_history.h"

namespace auv::ui {
namespace {

std::optional<TimePoint> logStart(const WizardState& s) {
  if (!s.log) return std::nullopt;
  const std::string* start = s.log->metadataValue("start");
  if (!start) return std::nullopt;
  try {
    return parseIsoUtc(*start, "start");
  } catch (const InputError&) {
    return std::nullopt;  // another clock format: the age is then unknown
  }
}

}  // namespace

std::optional<discrepancy::PlanEstimate> sessionEstimate(const WizardState& s) {
  if (!s.analysis) return std::nullopt;
  return discrepancy::planEstimate(*s.analysis, s.model_check ? &*s.model_check : nullptr, s.accepted_terms);
}

bool hasAnalysisToPlanFrom(const WizardState& s, HistoryStore* store, TimePoint now) {
  if (s.analysis) return true;
  if (!store || s.configuration_id.empty()) return false;
  try {
    return store->configuration(s.configuration_id) && store->latestAnalysis(s.configuration_id, now).has_value();
  } catch (const InputError&) {
    return false;
  }
}

std::vector<double> installedNow(const WizardState& s) {
  if (!s.vehicle) return {};
  const VehicleProfile& v = *s.vehicle;
  if (s.analysis && s.mission_installed_kg.size() == v.points.size()) return s.mission_installed_kg;
  std::vector<double> kg(v.points.size(), 0.0);
  if (v.kind == "glider") {
    for (std::size_t p = 0; p < v.points.size(); ++p)
      for (int i = 0; i < kSlocumItemCount; ++i)
        if (v.points[p].name == slocumItemName(static_cast<SlocumItem>(i)))
          kg[p] = s.tank.ballast.item_kg[static_cast<std::size_t>(i)];
    return kg;
  }
  for (std::size_t p = 0; p < kg.size() && p < s.crane.installed_kg.size(); ++p) kg[p] = s.crane.installed_kg[p];
  return kg;
}

PlanBasis planBasis(const WizardState& s, HistoryStore* store, TimePoint now, PlanPolicy policy) {
  if (!s.vehicle) throw InputError("vehicle", "no vehicle chosen", "go back to the vehicle page");
  const VehicleProfile& v = *s.vehicle;
  PlanBasis b;
  // What the history holds for the configuration: the same core gathering
  // as 'auvballast plan --config'.
  const bool in_history = store && !s.configuration_id.empty() && store->configuration(s.configuration_id).has_value();
  HistoryPlanInputs h;
  if (in_history) h = planInputsFromHistory(*store, s.configuration_id, v, now);
  b.total_mass_kg = h.total_mass_kg;

  nlohmann::json report;
  if (const auto e = sessionEstimate(s)) {
    b.from_session = true;
    b.source = e->source;
    report = analysis::toJson(e->report);
    b.analysis_name = "this session's analysis" + (s.analysis->log_name.empty() ? "" : " of " + s.analysis->log_name);
    b.measured_at = logStart(s);
  } else {
    if (!h.analysis) {
      throw InputError("analysis", "configuration " + s.configuration_id + " has no analysed mission in the history",
                       "run the post-mission mode on a log of this configuration first");
    }
    report = h.analysis->result;
    b.analysis_id = h.analysis->id;
    b.measured_at = h.analysis->at;
    b.analysis_name = "history analysis #" + std::to_string(h.analysis->id) + " of " + toIsoUtc(h.analysis->at).substr(0, 10);
  }
  b.report = report;
  const std::optional<MeasuredWater> measured = h.measured_water;
  if (measured && (!report.contains("net_buoyancy_kg") || !report["net_buoyancy_kg"].is_number()))
    b.measured_at = h.measured_water_at;
  b.start = planStartFromReport(v, report, b.analysis_name, policy, b.total_mass_kg, measured);

  b.installed_kg = installedNow(s);
  if (s.analysis && s.mission_installed_kg.size() == v.points.size()) {
    b.installed_source = "as flown in the analysed mission";
  } else if (h.installed) {
    b.installed_source = "history, " + toIsoUtc(h.installed->installed_at).substr(0, 10);
  } else {
    b.installed_source = "as entered";
  }
  return b;
}

NextMissionWater nextWaterOf(const WizardState& s) {
  const PlannedWater op = s.next_water.value_or(PlannedWater{});
  return nextMissionWater(op, s.next_deepest_m, s.next_water_source);
}

PreMissionInput preMissionInput(const WizardState& s, const PlanBasis& b) {
  PreMissionInput in;
  in.installed_kg = b.installed_kg;
  in.estimate = b.start.estimate;
  in.next = nextWaterOf(s);
  in.policy = s.policy;
  in.use_optional_pieces = s.crane.use_optional_pieces && s.policy != PlanPolicy::Classic;
  in.classic_computed_imbalance_kg = b.start.classic_computed_imbalance_kg;
  return in;
}

std::vector<ChecklistStep> checklistSteps(const PreMissionPlan& plan) {
  std::vector<ChecklistStep> removals, additions;
  for (std::size_t p = 0; p < plan.points.size(); ++p) {
    std::vector<PieceCount> pieces = plan.points[p].pieces;
    std::sort(pieces.begin(), pieces.end(), [](const PieceCount& a, const PieceCount& c) { return a.size_kg > c.size_kg; });
    for (const auto& pc : pieces) {
      if (pc.count < 0) removals.push_back({p, pc.size_kg, pc.count});
      if (pc.count > 0) additions.push_back({p, pc.size_kg, pc.count});
    }
  }
  removals.insert(removals.end(), additions.begin(), additions.end());
  return removals;
}

int massDecimals(const std::vector<double>& piece_sizes_kg) {
  int d = 1;
  for (double s : piece_sizes_kg) {
    while (d < 4 && std::abs(s * std::pow(10.0, d) - std::round(s * std::pow(10.0, d))) > 1e-6) ++d;
  }
  return d;
}

nlohmann::json preMissionReportJson(const WizardState& s, const PlanBasis& b, const std::string& created_at) {
  if (!s.plan || !s.vehicle) throw InputError("plan", "nothing planned yet", "go back to the pre-mission page");
  nlohmann::json j = toJson(*s.plan);
  j["format"] = "auvballast-pre-mission";
  j["created_at"] = created_at;
  j["config"] = s.configuration_id;
  j["vehicle_name"] = s.vehicle->name;
  j["sources"] = {{"analysis", b.analysis_name},
                  {"installed", b.installed_source},
                  {"water", s.next_water_source}};
  if (b.measured_at) j["sources"]["analysis_water_measured_at"] = toIsoUtc(*b.measured_at);
  const std::vector<double> planned = installedAfterPlan(b.installed_kg, *s.plan);
  const std::vector<double>& actual = s.actually_installed_kg.size() == planned.size() ? s.actually_installed_kg : planned;
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t i = 0; i < s.vehicle->points.size(); ++i) {
    points.push_back({{"name", s.vehicle->points[i].name},
                      {"before_kg", i < b.installed_kg.size() ? b.installed_kg[i] : 0.0},
                      {"planned_kg", planned[i]},
                      {"actual_kg", actual[i]}});
  }
  const InstalledPrediction pr = predictInstalled(*s.vehicle, *s.plan, b.installed_kg, actual);
  bool differs = false;
  for (std::size_t i = 0; i < planned.size(); ++i) differs = differs || std::abs(actual[i] - planned[i]) > 5e-5;
  j["installed"] = {{"points", points},
                    {"differs_from_plan", differs},
                    {"predicted",
                     {{"net_buoyancy_kg", pr.net_buoyancy_kg},
                      {"net_buoyancy_sigma_kg", pr.net_sigma_kg},
                      {"pitch_deg", pr.pitch_deg},
                      {"pitch_sigma_deg", pr.pitch_sigma_deg},
                      {"roll_deg", pr.roll_deg},
                      {"roll_sigma_deg", pr.roll_sigma_deg},
                      {"in_band", {{"net_buoyancy", pr.buoyancy_in_band}, {"pitch", pr.pitch_in_band}, {"roll", pr.roll_in_band}}},
                      {"safe", pr.safe}}}};
  const std::vector<ChecklistStep> steps = checklistSteps(*s.plan);
  int done = 0;
  for (std::size_t i = 0; i < steps.size() && i < s.checklist_done.size(); ++i) done += s.checklist_done[i] ? 1 : 0;
  j["checklist"] = {{"steps", steps.size()}, {"ticked", done}};
  return j;
}

}  // namespace auv::ui
