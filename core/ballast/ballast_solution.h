#pragma once
// The solver's answer: the move (signed piece counts per point and size) and
// what the vehicle will do after it, with plain sentences for the technician.
#include "common/message.h"
#include <Eigen/Core>
#include <string>
#include <vector>

namespace auv {

struct BallastSolution {
  std::vector<std::vector<int>> delta;  // delta[point][size], signed piece counts (negative = remove)
  std::vector<double> add_kg;           // per point, signed
  double net_buoyancy_kg = 0;           // predicted after the move, positive = too light
  Eigen::Vector3d cg_m = Eigen::Vector3d::Zero();
  double pitch_deg = 0, roll_deg = 0;   // predicted static attitude (exact, hydrostatics/static_trim.h)
  bool buoyancy_in_band = false, pitch_in_band = false, roll_in_band = false;
  std::vector<Message> notes;           // one sentence per point or decision (ballast_messages.h)
  std::vector<Message> warnings;        // unreachable bands, unsafe states (ballast_messages.h)
};

}  // namespace auv
