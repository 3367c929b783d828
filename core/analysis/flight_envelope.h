#pragma once
// Constant-command legs an AUV did not fly as commanded, found before any
// estimate is trusted. Two failures a technician must hear about, because
// the log then measures little of the ballast and a ballast plan alone will
// not cure them:
//  - the depth could not be held: for most of a leg the elevator sat at a
//    stop while the vehicle stayed metres shallower than commanded (too
//    light or too stern-heavy for its planes at that speed: it may never
//    leave the surface) or deeper (too heavy or too bow-heavy);
//  - porpoising: the depth loop limit-cycles (pitch swinging by tens of
//    degrees every half minute), so the leg holds no steady flight. Low BG
//    or weak heave damping against the autopilot's gains do this; the cure
//    is the autopilot or BG, not weights along the hull.
// The elevator's stop is read from the log: a clipped channel piles up at
// its extreme value, a free one does not.
#include <optional>
#include <vector>

#include "analysis/segments.h"

namespace auv::analysis {

struct AnalysisReport;

struct DepthNotHeld {
  double seconds = 0.0;          // leg time at the stop and off the command
  double depth_error_m = 0.0;    // median depth - command over those legs (< 0: shallower)
  double elevator_stop_deg = 0.0;
  int legs = 0;
};

struct Porpoising {
  double seconds = 0.0;
  double pitch_sd_deg = 0.0;  // the largest leg's
  double period_s = 0.0;      // median over the legs, from pitch up-crossings
  int legs = 0;
};

struct FlightEnvelope {
  std::optional<DepthNotHeld> too_light;  // shallower than commanded, elevator at a stop
  std::optional<DepthNotHeld> too_heavy;  // deeper than commanded, elevator at a stop
  std::optional<Porpoising> porpoising;
  double leg_seconds = 0.0;  // constant-command time examined
};

struct EnvelopeOptions {
  double settle_s = 120.0;          // a new depth is reached within this after a command step
  double min_leg_s = 300.0;         // shorter legs are not judged
  double stop_band_deg = 0.3;       // within this of the extreme = at the stop
  double min_stop_fraction = 0.02;  // of the log's elevator samples: a real clip
  double min_stop_deg = 5.0;        // a smaller extreme is no stop
  double at_stop_fraction = 0.5;    // of a leg's samples: the leg flew at the stop
  double depth_error_m = 2.0;       // and this far off the command (median)
  double porpoise_pitch_sd_deg = 5.0;
  double porpoise_max_steady_cover = 0.25;  // of the leg covered by operating windows
};

// `command_cuts`: where the depth command stepped or the propeller speed
// changed (segments.cpp); `operating`: the windows the estimation uses.
FlightEnvelope flightEnvelope(const MissionLog& log, const TimeSeries& depth, const std::vector<TimeWindow>& command_cuts,
                              const std::vector<Segment>& operating, const SegmentOptions& so,
                              const EnvelopeOptions& o = {});

// A warning per finding in `rep` (analysis.depth_not_held_light/_heavy,
// analysis.porpoising) and details.flight_envelope.
void reportFlightEnvelope(const FlightEnvelope& e, AnalysisReport& rep);

}  // namespace auv::analysis
