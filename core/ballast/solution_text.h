#pragma once
// The sentences a technician reads: what to do at each point and why the
// solver stopped where it did.
#include <string>
#include <vector>

#include "common/message.h"
#include "vehicle/vehicle_profile.h"

namespace auv::ballast {

std::string kgText(double kg);             // "1.20 kg"
std::string signedKgText(double kg);       // "+1.20 kg"
std::string degText(double deg);           // "0.50°"
std::string signedDegText(double deg);     // "+0.50°"
std::string sizeText(double kg);           // "1.2 kg" (piece sizes, shortest exact form)

// "Fore / starboard: add 2 × 4.8 kg and 1 × 1.2 kg (+10.80 kg; 0.00 -> 10.80 kg of 40.00 kg)."
// (ids ballast.point / ballast.point_no_change, ballast_messages.h)
Message pointNote(const AdjustmentPoint& point, const std::vector<double>& sizes_kg, const int* delta,
                  double before_kg, double after_kg);

}  // namespace auv::ballast
