#pragma once
// Operating segments found in the data rather than in a fixed 40-60 % window
// (thesis §3.2): vertical phases from the depth rate with hysteresis, and,
// inside level phases, the windows of steady flight (command, speed and
// propeller speed constant within tolerance bands) that the estimation uses.
// Each channel is read on its own time base; nothing compares floats for
// equality.
#include <string>
#include <vector>

#include "common/message.h"
#include "analysis/series_tools.h"
#include "missionlog/mission_log.h"

namespace auv::analysis {

enum class SegmentKind {
  kSurface,  // shallower than the surface threshold
  kDive,     // descending (depth rate above the threshold)
  kClimb,    // ascending
  kLevel,    // depth rate within the level band
  kSteady,   // AUV: steady level flight inside a level phase (used for estimation)
  kGlide,    // the steady part of a dive or climb (used for estimation): a glider's glides, an
             // AUV's pitch-limited depth changes and the dives of one that cannot hold depth
             // (averaged_legs.h)
};
const char* toString(SegmentKind kind);

struct Segment {
  SegmentKind kind = SegmentKind::kLevel;
  double start_s = 0.0;
  double end_s = 0.0;
  // For kGlide: the phase it belongs to (kDive or kClimb).
  SegmentKind phase = SegmentKind::kLevel;
  // An averaged leg (averaged_legs.h): the boundaries of the whole
  // oscillation cycles it spans (front = start_s, back = end_s); empty for a
  // steady window.
  std::vector<double> cycle_bounds_s;
  bool averaged() const { return !cycle_bounds_s.empty(); }
  double duration() const { return end_s - start_s; }
  TimeWindow window() const { return {start_s, end_s}; }
};

struct SegmentOptions {
  bool glider = false;               // operating windows are glides, not level legs
  double surface_depth_m = 1.0;      // shallower = at the surface
  double surface_hysteresis_m = 0.5;  // must go this much deeper to leave the surface
  double rate_window_s = 20.0;       // boxcar width of the depth rate
  // The depth rate inside an averaged leg's cycle products (averaged_legs.h):
  // short enough to follow a limit cycle of 15-20 s.
  double cycle_rate_window_s = 4.0;
  double dive_rate_mps = 0.05;       // |depth rate| above this enters dive/climb
  double level_rate_mps = 0.02;      // |depth rate| below this enters level
  double min_phase_s = 30.0;         // shorter phases are merged into a neighbour
  double max_gap_s = 120.0;          // longer data gaps split phases
  // Steady windows inside level phases (AUV).
  double settle_s = 30.0;            // dropped after a phase start or a command step
  double min_steady_s = 60.0;
  double depth_cmd_step_m = 0.5;     // a depth command change of this size starts a new leg
  double pitch_cmd_step_deg = 0.5;
  double speed_rate_limit_mps2 = 0.01;  // |d speed/dt| above this = changing speed
  double rpm_rate_limit_per_s = 1.0;    // |d rpm/dt| above this = changing propeller speed
  // Averaged legs (AUV): constant-command legs with no steady window, flown
  // in a slow oscillation, averaged over whole cycles (averaged_legs.h).
  bool average_oscillating_legs = true;
  double average_min_s = 600.0;        // whole cycles spanning at least this
  int average_min_cycles = 2;
  double average_depth_band_m = 3.0;   // the depth stays this close to the command after arriving
  double average_arrive_m = 1.0;       // arrived: first this close to the command
  double average_min_period_s = 60.0;  // faster "cycles" are noise
  double average_max_steady_cover = 0.5;  // legs mostly covered by steady windows keep those ...
  double average_min_swing_deg = 1.0;     // ... unless the smoothed pitch swings by this sd
  // Steady dives and climbs of an AUV (averaged_legs.h): the pitch-limited
  // middle of a depth change (40-90 s at +-15 deg on a HUGIN survey), or a
  // vehicle that cannot hold depth. At the same speed they fly a different
  // angle of attack from level flight, which separates hull lift from
  // stern-plane lift and both from the net buoyancy.
  bool auv_steady_glides = true;
  double auv_glide_min_s = 20.0;
  double auv_glide_max_pitch_sd_deg = 1.5;
  double auv_glide_plateau_deg = 1.0;  // the pitch within this of its median over the dive or climb
  double auv_glide_settle_s = 8.0;     // dropped at both ends of that plateau
  // Glides: trimmed at both ends (inflection, pump and battery moves).
  double glide_trim_s = 30.0;
};

struct Segmentation {
  std::vector<Segment> phases;     // surface/dive/climb/level, in time order
  std::vector<Segment> operating;  // kSteady or kGlide windows, in time order
  double max_depth_m = 0.0;
  std::vector<Message> notes;  // what was excluded and why
  // AUV: where the depth command stepped or the propeller speed changed,
  // extended by the settling time: the legs the mission planned lie between.
  std::vector<TimeWindow> command_cuts;
};

// Needs a `depth` channel (or `pressure`, converted with the standard
// ocean); throws InputError when neither has at least two samples.
Segmentation detectSegments(const MissionLog& log, const SegmentOptions& options);

// Depth on its own time base: the `depth` channel, or `pressure` converted
// (UNESCO 1983 at `latitude_deg`) when the log has no depth.
TimeSeries depthSeries(const MissionLog& log, double latitude_deg);

}  // namespace auv::analysis
