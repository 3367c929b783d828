#pragma once
// Local polynomial least-squares fits (Savitzky-Golay) on a uniform grid: the
// smoothed value and its first and second derivatives, so the equation error
// can use velocities and accelerations of logged states without amplifying
// sample-to-sample noise. A quartic fit over a few seconds keeps the peaks
// of pitch manoeuvres that a quadratic over the same window flattens (a
// biased q and q_dot would look like extra damping). Near the ends and next
// to gaps (NaN) the window shrinks symmetrically; fewer than `min_half`
// samples per side gives NaN.
#include <vector>

namespace auv::discrepancy {

struct Smoothed {
  std::vector<double> value, d1, d2;
};

// `y` on a grid of spacing dt; half window `half` samples (window 2 half + 1),
// polynomial `order` (2..6, at most 2 m where m is the half window used).
Smoothed savitzkyGolay(const std::vector<double>& y, double dt, int half, int order = 4, int min_half = 2);

}  // namespace auv::discrepancy
