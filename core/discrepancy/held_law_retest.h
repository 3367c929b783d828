#pragma once
// A buoyancy law the analysis fitted from legs whose pitch it read as true,
// when the check then found the pitch sensor biased. A biased pitch moves
// every leg's angle of attack, and where the speeds change with depth or
// with the hours the legs show that as a hull law: on hugin_concealed_bench
// a 1 deg bias became a thermal expansion of 2.0-2.4e-4 1/degC, named first
// and written into the hull by --accept. The log is analysed again with the
// found bias taken out (analysis/attitude_sensor_bias.h); a law the
// corrected legs no longer show is withdrawn from missing_physics and from
// what --accept writes, and a note says why.
#include "analysis/analysis_report.h"
#include "discrepancy/model_check.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::discrepancy {

// `analysis` is the log's analysis the check held (its installed pieces and
// a roll test's BG are reused). No-op for gliders, without a found pitch
// sensor bias, or without a held law among the findings.
void retestHeldLawsWithFoundPitchBias(const MissionLog& log, const VehicleProfile& v,
                                      const analysis::AnalysisReport& analysis, ModelCheckResult& result);

}  // namespace auv::discrepancy
