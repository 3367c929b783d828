#pragma once
// HUGIN crane weighing (thesis §4.2, §4.4): the vehicle hangs from two ropes,
// fore and aft, each with a crane scale at its starboard and port end, and
// the crane hook carries a fifth scale for the total. The four part readings
// are treated as point masses at the rope ends (eq. 4.1). The lateral rope
// offset (thesis: +-0.25 m) is an explicit, editable assumption; the CG
// height cannot be observed by hanging and comes from the vehicle profile.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "common/message.h"

#include "hydrostatics/mass_properties.h"

namespace auv {

struct CraneWeighing {
  std::array<double, 4> scales_kg{};  // FS, FP, AS, AP readings (kgf)
  double total_kg = 0.0;              // hook scale
  double rope_x_fore_m = 0.0;         // rope stations, vehicle axes
  double rope_x_aft_m = 0.0;
  double rope_y_m = 0.25;             // rope ends at +-rope_y_m
  double scale_resolution_kg = 0.5;   // one display step of the crane scales
  double sum_tolerance_kg = 2.0;      // accepted |sum(parts) - total|
  double cg_z_m = 0.0;                // from the profile: z_B + BG
};

struct CraneResult {
  MassProperties mass;                  // total mass = hook reading, CG from the parts
  Eigen::Vector3d cg_sigma_m = Eigen::Vector3d::Zero();
  double sum_of_parts_kg = 0.0;
  double sum_mismatch_kg = 0.0;  // sum(parts) - total
  std::vector<Message> warnings;  // weighing_messages.h ids
};

// Throws InputError for negative or non-finite readings, ropes at the same
// station, or a part sum that disagrees with the total by more than 5x the
// tolerance (a mis-typed reading); warns between 1x and 5x.
CraneResult weighCrane(const CraneWeighing& in);

}  // namespace auv
