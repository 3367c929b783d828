#pragma once
// h-moment-arm correction (Baird 2007, §4.3): h is how far G sits below B;
// about 6 mm makes the glider self-righting without being sluggish. Two
// things change it without touching buoyancy or pitch: swapping a disk weight
// between the top and bottom seat of its column (A, B, C), and moving lead
// between the upper and lower aft bottles. We try the report's eight disk
// arrangements, give each the aft-bottle shift that brings h closest to the
// target, and pick the one that gets closest (ties: fewer swaps, less lead).
#include <array>

#include "weighing/slocum_ballast.h"
#include "weighing/slocum_layout.h"

namespace auv {

struct DiskArrangement {
  int number = 0;                // report numbering: 0 none, 1 A, 2 B, 3 C, 4 A+B, 5 A+C, 6 B+C, 7 A+B+C
  std::array<bool, 3> swap{};    // columns A, B, C swapped top <-> bottom
  double h_after_swap_m = 0.0;   // before the aft-bottle shift
  double aft_shift_kg = 0.0;     // moved from the lower to the upper aft bottle (negative: downward)
  double h_m = 0.0;              // after the shift
  bool reaches_target = false;   // within half a lead-shot piece of the target
  SlocumBallast after;
};

struct HArmCorrection {
  double h_before_m = 0.0;
  double target_m = 0.0;
  std::array<DiskArrangement, 8> arrangements;
  int chosen = 0;

  const DiskArrangement& best() const { return arrangements[static_cast<std::size_t>(chosen)]; }
};

// `h_m`: z of G below the hull axis for the glider of mass `glider_mass_kg`
// with ballast `now` (after the roll correction, so G is straight below B).
HArmCorrection correctHArm(const SlocumLayout& layout, const SlocumBallast& now, double glider_mass_kg,
                           double h_m);

}  // namespace auv
