#pragma once
// Shared fixtures for the Slocum weighing tests: the shipped profile and the
// report's App. B / App. C glider states.
#include <string>

#include "vehicle/profile_loader.h"
#include "weighing/slocum_ballast.h"
#include "weighing/slocum_layout.h"

namespace auv::slocum_test {

inline VehicleProfile profile() {
  return loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/slocum_g2.json");
}

inline SlocumLayout layout() { return slocumLayout(profile()); }

// App. B after the tank step (the masses the session typed in): bottles
// 288/288 aft, 152/152 bow, rails 60/60, disks 550 A-top, 555 C-top,
// 555 B-bottom, battery at 0.
inline SlocumBallast appendixBAfterTankStep() {
  SlocumBallast b;
  b.at(kForePort) = 0.152;
  b.at(kForeStarboard) = 0.152;
  b.at(kAftUpper) = 0.288;
  b.at(kAftLower) = 0.288;
  b.at(kRailPort) = 0.060;
  b.at(kRailStarboard) = 0.060;
  b.disks[0] = {0.550, 0.0};
  b.disks[1] = {0.0, 0.555};
  b.disks[2] = {0.555, 0.0};
  return b;
}

inline constexpr double kAppBMassKg = 52.302;      // new_mass after the tank step
inline constexpr double kAppBBatteryKg = 7.86;
inline constexpr double kAppCMassKg = 50.13;
inline constexpr double kAppCBatteryKg = 7.89;
inline constexpr double kReportBeta = 0.09;        // both sessions' initial roll

}  // namespace auv::slocum_test
