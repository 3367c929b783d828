#pragma once
// Priority 1 (thesis §5.4): net buoyancy. It depends on the total mass added
// only, so it is settled first and exactly, over every total the kit can
// make; the later phases search only inside the resulting window of totals.
#include <cstdint>
#include <vector>

#include "ballast/point_options.h"

namespace auv::ballast {

struct BuoyancyClass {
  double negative_kg = 0;       // how far below zero net buoyancy (0 = never negative)
  double band_violation_kg = 0; // how far outside [net_lo, net_hi]
};

struct TotalWindow {
  std::int64_t lo_q = 0, hi_q = 0;  // totals added (quanta) in the best class
  BuoyancyClass best;
};

// Every total mass change the points can make together (quanta, ascending).
std::vector<std::int64_t> reachableTotals(const std::vector<PointOptions>& points);

BuoyancyClass classify(double net_kg, double net_lo_kg, double net_hi_kg);

// net_now_kg: net buoyancy before the move. The window of the best class.
TotalWindow bestWindow(const std::vector<std::int64_t>& totals, double net_now_kg, double net_lo_kg,
                       double net_hi_kg);

// The window of totals whose class is no worse than `limit`; empty
// (lo_q > hi_q) when none is.
TotalWindow windowNoWorseThan(const std::vector<std::int64_t>& totals, double net_now_kg, double net_lo_kg,
                              double net_hi_kg, const BuoyancyClass& limit);

// The same window for any (continuous) total, widened by a quantum each side:
// used to ask whether any masses at all could do better.
TotalWindow continuousWindow(double net_now_kg, double net_lo_kg, double net_hi_kg, const BuoyancyClass& limit);

}  // namespace auv::ballast
