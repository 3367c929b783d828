#include "discrepancy/plan_estimate.h"

#include <algorithm>
#include <cmath>

namespace auv::discrepancy {
namespace {

bool usable(double value, double sigma) { return std::isfinite(value) && std::isfinite(sigma) && sigma > 0.0; }

}  // namespace

double adoptedSigma(double analysis_value, double analysis_sigma, double check_value, double check_sigma) {
  return std::hypot(std::max(check_sigma, analysis_sigma), check_value - analysis_value);
}

PlanEstimate planEstimate(const analysis::AnalysisReport& analysis, const ModelCheckResult* check,
                          const std::vector<std::string>& accepted_terms) {
  PlanEstimate out{analysis, EstimateSource::kAnalysis};
  if (analysis.vehicle_kind == "glider") return out;
  // An analysis calibrated with an earlier mission across a known weight
  // change has had a calibration experiment the check's single-log fit has
  // not: its estimate stays (as model-check --config reports it).
  const nlohmann::json& d = analysis.details;
  if (analysis.net_buoyancy_kg.known && d.contains("auv_estimate") &&
      d["auv_estimate"].value("history_segments_used", 0) > 0) {
    out.source = EstimateSource::kHistoryJoint;
    return out;
  }
  if (!check) return out;
  bool any = false;
  for (const auto& m : check->missing_physics)
    for (const auto& id : accepted_terms) any = any || m.id == id;
  const bool replay_only = !any && !analysis.net_buoyancy_kg.known;
  if ((!any && !replay_only) || !usable(check->net_buoyancy_kg, check->net_buoyancy_sigma_kg)) return out;
  // An accepted pitch sensor bias: the analysis side is the log's analysis
  // with the bias taken out and its sigma carried, not the one that read
  // the biased pitch as true (held_law_retest.h).
  const auto& free = check->analysis_without_pitch_bias;
  if (free && std::find(accepted_terms.begin(), accepted_terms.end(), "pitch_sensor_bias") != accepted_terms.end() &&
      usable(free->net_buoyancy_kg, free->net_buoyancy_sigma_kg)) {
    out.report.net_buoyancy_kg = {true, free->net_buoyancy_kg, free->net_buoyancy_sigma_kg, {}};
    if (free->has_cg_x && usable(free->cg_x_mm, free->cg_x_sigma_mm))
      out.report.cg_x_mm = {true, free->cg_x_mm, free->cg_x_sigma_mm, {}};
  }
  const auto adopt = [](analysis::EstimatedValue& into, double value, double sigma) {
    const double s = into.known && usable(into.value, into.sigma) ? adoptedSigma(into.value, into.sigma, value, sigma) : sigma;
    into = {true, value, s, ""};
  };
  adopt(out.report.net_buoyancy_kg, check->net_buoyancy_kg, check->net_buoyancy_sigma_kg);
  if (check->has_cg && usable(check->cg_x_mm, check->cg_x_sigma_mm))
    adopt(out.report.cg_x_mm, check->cg_x_mm, check->cg_x_sigma_mm);
  out.source = replay_only ? EstimateSource::kModelCheckReplay : EstimateSource::kModelCheck;
  return out;
}

}  // namespace auv::discrepancy
