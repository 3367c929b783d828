#pragma once
// The glider's pre-mission answer for the wizard, through the same core calls
// as `auvballast model-check --target-...` (or `analyze --target-...` when the
// model check did not run): the target water resolved from the imported log
// (core/analysis/glider_target.h), the mass to add with the vehicle as the
// model check found it (discrepancy/glider_ballast_answer.h) and where the
// grams go (planning/glider_ballast_plan.h). No arithmetic of its own.
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "analysis/glider_target.h"
#include "wizard/wizard_state.h"

namespace auv::ui {

// The technician's choice of target water on the glider pre-mission page.
struct GliderTargetChoice {
  enum class Kind { kLogDeepest, kDensity, kPressureTemperature, kDepth };
  Kind kind = Kind::kLogDeepest;
  double density_kgm3 = NAN;
  double pressure_dbar = NAN;
  double temperature_degC = NAN;
  double salinity_psu = NAN;  // optional with pressure + temperature
  double depth_m = NAN;
};

// The CLI flags the choice stands for (salinity turns p + T into a density).
analysis::GliderTargetRequest targetRequest(const GliderTargetChoice& c);

struct GliderAnswer {
  bool ok = false;
  std::string error;             // InputError text when !ok
  analysis::GliderTarget target;
  nlohmann::json report;         // the analysis JSON, model check and joint answer merged (as model-check writes it)
  nlohmann::json plan;           // planGliderBallast: points[], seaglider{}, roll_trim{}, cannot_tell[], warnings[]
  bool joint = false;            // the mass to add comes from the model check's joint fit
  std::vector<std::string> terms_used;
  double mass_drift_g_per_h = 0.0;
};

GliderAnswer gliderAnswer(const WizardState& s, const GliderTargetChoice& c);

}  // namespace auv::ui
