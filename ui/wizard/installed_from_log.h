#pragma once
// The installed adjustment masses a log may carry in its header line
// `# configuration: fs=12.0 fp=12.0 as=9.6 ap=9.6` (kg per point; a point is
// named by its profile id, e.g. fore_starboard, or by the initials of that
// id, e.g. fs). The post-mission page uses it when the history has nothing.
#include <optional>
#include <string>
#include <vector>

#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::ui {

// Masses in profile point order, or nothing when the line is absent or is
// not a list of point=kg (e.g. just a configuration ID). Points the line
// does not name are 0.
std::optional<std::vector<double>> installedFromLogHeader(const MissionLog& log, const VehicleProfile& v);

}  // namespace auv::ui
