#pragma once
// Attitude sensor biases a model check found on an AUV and the operator
// accepted (`model-check --accept` writes them into the profile under
// "model_check": {"terms": {"pitch_sensor_bias": deg, "roll_sensor_bias":
// deg}}, each the reading minus the true angle). The analysis takes them out
// of the logged pitch and roll before anything else reads them: a 1 deg pitch
// bias moves every leg's angle of attack, and read as true it put a HUGIN's
// net buoyancy 3-4 kg off and named a thermal expansion the hull does not
// have (hugin_concealed_bench truth 5501).
#include <optional>

#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis {

struct AttitudeSensorBias {
  double pitch_deg = 0.0;  // reading minus true
  double roll_deg = 0.0;
  // The check's sigma of each, as accepted (0: none recorded). A tenth of a
  // degree of pitch moves a HUGIN's net buoyancy by about 0.6 kg, so the
  // analysis carries it into its own sigmas.
  double pitch_sigma_deg = 0.0, roll_sigma_deg = 0.0;
  bool any() const { return pitch_deg != 0.0 || roll_deg != 0.0; }
};

// The profile's accepted biases; zero where it has none. The sigmas are the
// latest acceptance's (model_check.accepted[] {id, sigma}). Gliders keep
// theirs in flight_model.pitch_offset_deg (their own flight model applies it).
AttitudeSensorBias acceptedAttitudeBias(const VehicleProfile& v);

// The log with the biases taken out of `pitch` and `roll` (the commands stay:
// they are the attitude the operator asked for). nullopt: nothing to remove.
std::optional<MissionLog> withAttitudeBiasRemoved(const MissionLog& log, const AttitudeSensorBias& b);

}  // namespace auv::analysis
