#pragma once
// Core's advice names adjustment points by their profile ids ("fore_port");
// the technician reads the profile's labels ("Bow bottle / port").
#include <QString>

#include "vehicle/vehicle_profile.h"

namespace auv::ui {

// `text` with every point id of `vehicle` replaced by its label (whole words,
// the longest id first so that "fore_port" is not half-replaced inside a
// longer id).
QString withPointLabels(QString text, const VehicleProfile& vehicle);

}  // namespace auv::ui
