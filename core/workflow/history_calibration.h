#pragma once
// The earlier missions of a configuration as calibration experiments for
// the next analysis (issue 11 item 3): the steady segments its latest
// analysis recorded (details.auv_estimate.steady_segments) and the pieces
// installed then (details.installed_kg). With the pieces installed now, the
// known change of mass and moment between them calibrates the hydrodynamics
// jointly with the ballast state.
#include <string>
#include <vector>

#include "analysis/mission_analysis.h"
#include "history/timestamp.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

class HistoryStore;

// Empty when the configuration has no analysed AUV mission with steady
// segments and installed pieces of this vehicle's points. An analysis of
// `current_log` (the log about to be analysed, as its report names it) is
// not an earlier mission: its segments would count twice.
std::vector<analysis::HistoryMission> historyCalibrationMissions(HistoryStore& store, const std::string& config_id,
                                                                 const VehicleProfile& v, TimePoint now,
                                                                 const std::string& current_log);

// A configuration's history into an analysis's options (`analyze` and
// `model-check` with --config): the pieces that flew, from the history's
// installed state unless a.installed_kg is given, the configuration's BG
// from its roll test unless a.bg_m is given, its pitch sensor level check
// as a.pitch_alignment_sigma_deg (a caller with its own value sets it
// after), and the calibration experiment above (a.log_name is the log
// about to be analysed). Throws InputError naming the store when the
// configuration is not in it.
void addConfigurationHistory(HistoryStore& store, const std::string& config_id, const VehicleProfile& v, TimePoint now,
                             analysis::AnalysisOptions& a);

}  // namespace auv
