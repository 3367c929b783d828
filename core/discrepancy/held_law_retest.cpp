#include "discrepancy/held_law_retest.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "analysis/mission_analysis.h"
#include "common/units.h"
#include "discrepancy/physics_terms.h"

namespace auv::discrepancy {
namespace {

bool isHeldLaw(const MissingPhysics& m, const analysis::AnalysisReport& r) {
  if (m.id != "hull_compressibility" && m.id != "thermal_expansion" && m.id != "mass_drift") return false;
  const analysis::CalibrationParameter* p = analysis::calibrationParameter(r, m.id);
  return p && p->used;
}

// The options the analysis ran with: all of them (history, BG, priors) when
// analyzeMission made the report, else as far as its JSON details keep them.
analysis::AnalysisOptions optionsOf(const analysis::AnalysisReport& r) {
  if (r.options) return *r.options;
  analysis::AnalysisOptions a;
  a.log_name = r.log_name;
  if (r.details.contains("installed_kg") && r.details["installed_kg"].is_array())
    a.installed_kg = r.details["installed_kg"].get<std::vector<double>>();
  const nlohmann::json* e = r.details.contains("auv_estimate") ? &r.details["auv_estimate"] : nullptr;
  if (e && e->value("bg_source", "") == "--bg-mm" && e->contains("bg_mm") && (*e)["bg_mm"].is_number())
    a.bg_m = units::mmToM((*e)["bg_mm"].get<double>());
  return a;
}

}  // namespace

void followFoundPitchBias(const MissionLog& log, const VehicleProfile& v, const analysis::AnalysisReport& analysis,
                          ModelCheckResult& result) {
  if (v.kind == "glider") return;
  auto& found = result.missing_physics;
  const auto bias = std::find_if(found.begin(), found.end(), [](const MissingPhysics& m) { return m.id == "pitch_sensor_bias"; });
  if (bias == found.end()) return;
  const double increment_deg = bias->value - bias->profile_value;
  VehicleProfile corrected = v;
  nlohmann::json& mc = corrected.sections["model_check"];
  nlohmann::json& terms = mc["terms"];
  if (!terms.is_object()) terms = nlohmann::json::object();
  terms["pitch_sensor_bias"] = terms.value("pitch_sensor_bias", 0.0) + increment_deg;
  // Its sigma, as --accept would record it: carried into the ballast state's.
  mc["accepted"] = nlohmann::json::array({{{"id", "pitch_sensor_bias"}, {"sigma", bias->sigma}}});
  const analysis::AnalysisReport again = analysis::analyzeMission(log, corrected, optionsOf(analysis));
  if (again.net_buoyancy_kg.known) {
    ModelCheckResult::BiasFreeAnalysis b;
    b.pitch_bias_deg = increment_deg;
    b.pitch_bias_sigma_deg = bias->sigma;
    b.net_buoyancy_kg = again.net_buoyancy_kg.value;
    b.net_buoyancy_sigma_kg = again.net_buoyancy_kg.sigma;
    b.has_cg_x = again.cg_x_mm.known;
    if (b.has_cg_x) b.cg_x_mm = again.cg_x_mm.value, b.cg_x_sigma_mm = again.cg_x_mm.sigma;
    result.analysis_without_pitch_bias = b;
  }
  std::vector<MissingPhysics> kept;
  for (const MissingPhysics& m : found) {
    const analysis::CalibrationParameter* p = isHeldLaw(m, analysis) ? analysis::calibrationParameter(again, m.id) : nullptr;
    if (!p || p->used) {
      kept.push_back(m);
      continue;
    }
    result.accepted[*findTerm(m.id)] = 0.0;  // --accept must not write it
    char b[320];
    std::snprintf(b, sizeof b,
                  "%s %.3g %s (the analysis's, from the steady legs) withdrawn: with the pitch sensor bias of %.2f deg "
                  "taken out of the log the legs show no significant %s (%.3g +- %.2g); it was the bias read as true",
                  m.id.c_str(), m.value, m.unit.c_str(), increment_deg, m.id.c_str(), p->value, p->sigma);
    result.notes.emplace_back(b);
  }
  found = std::move(kept);
}

}  // namespace auv::discrepancy
