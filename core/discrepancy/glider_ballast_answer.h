#pragma once
// The glider's answer after a model check: grams to add for neutral at the
// target water with the pump at its zero, computed with the vehicle as the
// check found it (jointly fitted volume and accepted terms: compressibility
// and thermal expansion carry the volume to the target's p and T, a mass
// drift is carried to the end of the log, a pitch bias is removed from the
// flight model before the volume is fitted).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/glider_target.h"
#include "discrepancy/glider_check_model.h"
#include "discrepancy/model_check.h"

namespace auv::discrepancy {

struct GliderBallastAnswer {
  double mass_to_add_g = 0.0;
  double mass_to_add_sigma_g = 0.0;
  double mass_to_add_without_terms_g = 0.0;  // ballast-state-only fit, for comparison
  analysis::GliderTarget target;
  double mass_drift_g_per_h = 0.0;            // 0 unless accepted
  double mass_drift_sigma_g_per_h = 0.0;
  double hull_volume_m3 = 0.0;                // V0 at p = 0, T_ref, pump zero
  double mass_now_kg = 0.0;                   // at the end of the log
  double reference_temperature_degC = 0.0;
  double mass_change_at_end_g = 0.0;          // carried from the log's middle to its end
  double hours_to_end = 0.0;
  double pitch_bias_removed_deg = 0.0;
  double rival_spread_g = 0.0;                // largest change of the answer if a found term's rival were the truth
  double unconfirmed_spread_g = 0.0;          // largest sigma share of a candidate not accepted (its value x sqrt(inclusion))
  double compressibility_per_dbar = 0.0;      // in use (profile + accepted)
  double thermal_expansion_per_degC = 0.0;
  std::vector<std::string> terms_used;
};

GliderBallastAnswer gliderBallastAnswer(const GliderCheckModel& model, const ModelCheckResult& result,
                                        const analysis::GliderTarget& target);

// Sets the top-level mass_to_add_g / mass_to_add_sigma_g / target of a
// model-check report to the joint answer, keeps the analysis's figure under
// model_check.analysis_estimate and adds model_check.glider_ballast.
void mergeGliderAnswer(nlohmann::json& report, const GliderBallastAnswer& a);

}  // namespace auv::discrepancy
