#pragma once
// Legs flown in a slow oscillation. Some vehicles never settle on a leg: the
// depth autopilot limit-cycles with a period of several minutes (pitch
// +-3..10 deg, depth within a metre or two of the command), so no window is
// steady and the leg's speed would be lost to the estimation. Over whole
// cycles of that oscillation the pitch rate and the heave and pitch
// accelerations average to zero, so the leg's means satisfy the same steady
// balance (auv_steady_model.h) to first order; the cycle-to-cycle spread of
// the means is their honest uncertainty.
#include <optional>
#include <span>
#include <vector>

#include "analysis/auv_steady_model.h"
#include "analysis/auv_trim_estimation.h"
#include "analysis/segments.h"
#include "analysis/statistics.h"

namespace auv::analysis {

// Averaged legs (kSteady segments with cycle_bounds_s filled) for the
// constant-command legs of `log` that `steady` leaves mostly uncovered.
// `command_cuts`: where a depth or pitch command stepped or the propeller
// speed changed, already extended by the settling time. Returns them in
// time order; `steady` windows inside an averaged leg are to be dropped.
std::vector<Segment> averagedLegs(const MissionLog& log, const TimeSeries& depth,
                                  const std::vector<TimeWindow>& command_cuts, const std::vector<Segment>& steady,
                                  const SegmentOptions& o);

// Steady dives and climbs of an AUV: the pitch-limited middle of a depth
// change, or a vehicle that cannot hold its depth (the elevator at its
// stop, sinking or rising at a constant pitch). In each dive or climb
// phase, the longest run where the pitch stays within
// `o.auv_glide_plateau_deg` of its median, less `o.auv_glide_settle_s` at
// each end, at least `o.auv_glide_min_s`. No command cut is subtracted: the
// rpm step that often comes with a depth change settles inside the
// plateau's margins, and whether the balance holds there is checked by the
// calibration (glides_dropped). The steady balance holds with w from the
// depth rate (auv_steady_model.h). kGlide segments with `phase` kDive or kClimb.
std::vector<Segment> auvSteadyGlides(const MissionLog& log, const std::vector<Segment>& phases, const SegmentOptions& o);

// Mean of `s` over whole cycles: the sample mean over [bounds.front(),
// bounds.back()], its standard error from the spread of the per-cycle means
// (floored by the residual phase error of the cycle boundaries). NaN mean
// when fewer than two cycles hold samples.
MeanEstimate cycleMean(const TimeSeries& s, std::span<const double> bounds);

// Means of the balance's products (auv_steady_model.h) over [bounds.front(),
// bounds.back()] on the pitch channel's time base; needs `pitch` and `speed`
// (roll 0 without `roll`, elevator 0 without `elevator`). nullopt without samples.
std::optional<BalanceRegressors> cycleRegressors(const MissionLog& log, const TimeSeries& depth_rate,
                                                 std::span<const double> bounds);

// An averaged leg's means over its whole oscillation cycles, with the
// cycle-to-cycle spread as their standard errors. The cycle products need a
// depth rate that follows the cycle (`fast_rate`, SegmentOptions::
// cycle_rate_window_s; docs/decisions/analysis-segments.md): w from a
// flattened z_dot swings with the whole u sin(theta), and |w| w reads that
// swing as lift. The means take the segments' `depth_rate`.
void averageOverCycles(const MissionLog& log, const Segment& leg, const TimeSeries& depth_rate, const TimeSeries& fast_rate,
                       SteadySegmentMeans& m);

}  // namespace auv::analysis
