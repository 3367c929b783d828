#pragma once
// First-mission mode for a Slocum glider weighed in a tank (Baird 2007):
//   1. tank readings -> neutral mass at the deployment water -> bow/aft
//      bottle changes (whole grams, never ending heavy);
//   2. roll test (if recorded) -> G in the cross-section -> roll battery
//      angle, with wing-rail / bow-bottle shifts when the battery is not
//      enough;
//   3. h-moment arm -> disk-weight swaps and upper/lower aft-bottle shift.
// The recommendation is relative to the glider as it is now: as weighed, or
// as set after the tank step when the file records that (report App. B).
#include "firstmission/first_mission_report.h"
#include "vehicle/vehicle_profile.h"
#include "weighing/tank_weighing.h"

namespace auv {

// Throws InputError for a non-Slocum profile, a weighing for another
// vehicle, ballast above a capacity, or implausible readings (the field is
// named as in the weighing file).
FirstMissionReport slocumFirstMission(const VehicleProfile& vehicle, const TankWeighing& weighing);

}  // namespace auv
