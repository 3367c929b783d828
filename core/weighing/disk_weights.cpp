#include "weighing/disk_weights.h"

#include <algorithm>
#include <cmath>

namespace auv {
namespace {

// Report order of the seven swaps (§4.3: del_m1 ... del_m7).
constexpr std::array<std::array<bool, 3>, 8> kSwaps = {{{false, false, false},
                                                        {true, false, false},
                                                        {false, true, false},
                                                        {false, false, true},
                                                        {true, true, false},
                                                        {true, false, true},
                                                        {false, true, true},
                                                        {true, true, true}}};

int swapCount(const std::array<bool, 3>& s) { return int(s[0]) + int(s[1]) + int(s[2]); }

}  // namespace

HArmCorrection correctHArm(const SlocumLayout& L, const SlocumBallast& now, double M, double h_m) {
  const double res = L.mass_resolution_kg;
  const double z_up = L.item(kAftUpper).position_m.z();
  const double z_lo = L.item(kAftLower).position_m.z();
  // Half a piece moved between the aft bottles: the finest step in h.
  const double tolerance = 0.5 * res * (z_lo - z_up) / M + 1e-12;

  HArmCorrection hc;
  hc.h_before_m = h_m;
  hc.target_m = L.target_h_arm_m;
  for (std::size_t n = 0; n < kSwaps.size(); ++n) {
    DiskArrangement a;
    a.number = static_cast<int>(n);
    a.swap = kSwaps[n];
    a.after = now;
    double mz = M * h_m;
    for (std::size_t k = 0; k < 3; ++k) {
      if (!a.swap[k]) continue;
      auto& d = a.after.disks[k];
      // Top disk goes down, bottom disk goes up.
      mz += (d.top_kg - d.bottom_kg) * (L.disks[k].bottom_z_m - L.disks[k].top_z_m);
      std::swap(d.top_kg, d.bottom_kg);
    }
    a.h_after_swap_m = mz / M;
    // Moving u up from the lower bottle changes M z by u (z_up - z_lo).
    const double want = (M * hc.target_m - mz) / (z_up - z_lo);
    const double up_max = std::min(now.at(kAftLower), L.item(kAftUpper).capacity_kg - now.at(kAftUpper));
    const double down_max = std::min(now.at(kAftUpper), L.item(kAftLower).capacity_kg - now.at(kAftLower));
    a.aft_shift_kg = std::clamp(std::round(want / res) * res, -std::max(0.0, down_max), std::max(0.0, up_max));
    a.after.at(kAftUpper) += a.aft_shift_kg;
    a.after.at(kAftLower) -= a.aft_shift_kg;
    a.h_m = (mz + a.aft_shift_kg * (z_up - z_lo)) / M;
    a.reaches_target = std::abs(a.h_m - hc.target_m) <= tolerance;
    hc.arrangements[n] = a;
  }
  // Closest to the target wins; within the tolerance the simplest work wins.
  auto better = [&](const DiskArrangement& x, const DiskArrangement& y) {
    const double ex = std::abs(x.h_m - hc.target_m), ey = std::abs(y.h_m - hc.target_m);
    if (x.reaches_target != y.reaches_target) return x.reaches_target;
    if (!x.reaches_target && std::abs(ex - ey) > 1e-9) return ex < ey;
    if (swapCount(x.swap) != swapCount(y.swap)) return swapCount(x.swap) < swapCount(y.swap);
    return std::abs(x.aft_shift_kg) < std::abs(y.aft_shift_kg) - 1e-12;
  };
  hc.chosen = 0;
  for (std::size_t n = 1; n < hc.arrangements.size(); ++n) {
    if (better(hc.arrangements[n], hc.arrangements[static_cast<std::size_t>(hc.chosen)])) hc.chosen = static_cast<int>(n);
  }
  return hc;
}

}  // namespace auv
