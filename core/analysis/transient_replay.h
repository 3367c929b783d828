#pragma once
// --transients (AnalysisOptions::use_transients): whether a log's depth steps
// and propeller-speed changes are flown again through the profile's
// simulator model, and if so the replay attached to the steady calibration.
#include <optional>
#include <vector>

#include "analysis/analysis_report.h"
#include "analysis/auv_transient_fit.h"
#include "analysis/auv_trim_estimation.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis {

// `replay_unfit`: the log was flown too light or porpoising
// (flight_envelope.h). Skipped there and with a history calibration
// (ctx.history), said in rep (details.transients_skipped and a note);
// otherwise, with planes, elevator and speed, `fit` is built and its
// residuals join ctx (fit must outlive the calibration), and
// details.transient_windows says how many windows it holds.
// rho_kgm3, buoyancy_ref_kg: the calibration's reference water and buoyancy.
void attachTransientReplay(const MissionLog& log, const VehicleProfile& v, const std::vector<double>& installed_kg,
                           bool replay_unfit, bool has_planes, double rho_kgm3, double buoyancy_ref_kg,
                           std::optional<TransientFit>& fit, AuvTrimContext& ctx, AnalysisReport& rep);

}  // namespace auv::analysis
