#pragma once
// The deviation charts' CSV export: every logged sample of the plotted
// channels within the visible time window (not the thinned-out points drawn),
// as a mission-log CSV that the log import reads back.
#include <QString>
#include <vector>

#include "missionlog/mission_log.h"

namespace auv::ui {

// Rows of `log` within [x0_min, x1_min] (minutes since the log start) at which
// any of `channels` has a value, those channels only; the metadata records
// the window and `log_name`. Returns the number of rows written; throws
// InputError when the file cannot be written.
long writePlottedWindowCsv(const MissionLog& log, const std::vector<const LogChannel*>& channels, double x0_min,
                           double x1_min, const QString& log_name, const QString& path);

}  // namespace auv::ui
