#pragma once
// The analysis again, once the check has found a pitch sensor bias. The
// analysis balanced the steady legs with the logged pitch read as true; a
// 1 deg bias moves every leg's angle of attack, which put a HUGIN's net
// buoyancy 2.7 kg off (median, 3.8 of its sigmas; identification_bench
// --pitch-bias 1) and, where the speeds change with depth or with the hours, showed as a
// hull law (hugin_concealed_bench: thermal expansions of 2.0-2.4e-4 1/degC
// named first and written into the hull by --accept). The log is analysed
// again with the found bias taken out and its sigma carried
// (analysis/attitude_sensor_bias.h):
// - the result is kept as ModelCheckResult::analysis_without_pitch_bias, the
//   analysis side of the plan's estimate where the bias is accepted
//   (plan_estimate.h);
// - a held law the corrected legs no longer show is withdrawn from
//   missing_physics and from what --accept writes, and a note says why.
#include "analysis/analysis_report.h"
#include "discrepancy/model_check.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::discrepancy {

// `analysis` is the log's analysis the check held: the log is analysed again
// with the options it was made with (AnalysisReport::options: installed
// pieces, BG, the sensor's prior, the history's missions, which analyzeMission
// re-references to the new bias). No-op for gliders and without a found
// pitch sensor bias.
void followFoundPitchBias(const MissionLog& log, const VehicleProfile& v, const analysis::AnalysisReport& analysis,
                          ModelCheckResult& result);

}  // namespace auv::discrepancy
