#pragma once
// Constants the analysis takes from the vehicle profile (glider flight model,
// propeller law and torque) and from the log's metadata (latitude): read
// once here so the analysis, the model check and the overlay agree.
#include <optional>
#include <string>
#include <vector>

#include "common/message.h"
#include "analysis/auv_trim_estimation.h"
#include "analysis/glider_flight.h"
#include "missionlog/mission_log.h"
#include "vehicle/seaglider_calibration.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis {

// Flight-model constants for a glider profile: its optional "flight_model"
// section, else gliderflight's Slocum defaults (listed in `notes`).
GliderFlightConstants gliderConstantsFromProfile(const VehicleProfile& v, std::vector<Message>& notes);

// The number at `pos` of a metadata text ("12.5 kg" -> 12.5), NaN if none.
double parseNumberAfter(const std::string& s, std::size_t pos);

// The Seaglider constants a log carries in its metadata
// (MissionLog::seagliderConstants(): sg_cal_* and log_*), named after `file`
// for messages. Throws InputError (field "from") when the log has no
// sg_cal_mass or sg_cal_volmax (not a basestation per-dive file).
SeagliderCalibration seagliderCalibrationOf(const MissionLog& log, const std::string& file);

// Latitude from the log metadata (`latitude:`, `lat:` or `position: lat X ...`).
std::optional<double> latitudeFromMetadata(const MissionLog& log);

// The propeller reaction torque at 100 rpm the profile's simulator
// assumptions imply (rho n^2 D^5 K_Q0), 0 when the profile has none.
double profileTorqueAt100Rpm(const VehicleProfile& v, double rho);

// The propeller law (diameter, c1, c2, wake fraction) of the profile's
// actuators, nullopt when it has none.
std::optional<AuvTrimContext::PropellerLaw> propellerLawFromProfile(const VehicleProfile& v);

// The simulator's model of the vehicle (sim::loadVehicleModel), nullopt when
// the profile has no simulator sections.
std::optional<sim::VehicleModel> simModelFromProfile(const VehicleProfile& v);

}  // namespace auv::analysis
