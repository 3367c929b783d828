#pragma once
// Everything the operator has entered so far and the last computed report.
// Pages read and write this one object, so going back and forth loses nothing
// and the whole session can later be saved and resumed.
#include <optional>
#include <string>

#include "firstmission/first_mission_report.h"
#include "firstmission/hugin_first_mission.h"
#include "vehicle/vehicle_profile.h"

namespace auv::ui {

struct WizardState {
  std::string vehicles_dir;
  std::optional<VehicleProfile> vehicle;
  std::string configuration_id;
  std::string payload_note;
  CraneFirstMissionInput crane;  // weighing, installed, water, policy
  std::optional<FirstMissionReport> report;
  std::string last_error;
};

}  // namespace auv::ui
