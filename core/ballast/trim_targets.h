#pragma once
// The bands the search works against, in radians and kg. For the Exact
// policy they are the spec bands; for HalfWay they are the spec bands moved
// half-way from where the vehicle is now (never below zero net buoyancy).
#include "vehicle/vehicle_profile.h"

namespace auv::ballast {

struct TrimTargets {
  double net_lo_kg = 0, net_hi_kg = 0;
  double pitch_lo = 0, pitch_hi = 0;      // rad
  double roll_lo = 0, roll_hi = 0;        // rad
  double pitch_centre = 0, roll_centre = 0;  // rad, where the residual is zero
  double pitch_scale = 1, roll_scale = 1;    // rad, residual normalisation (spec tolerances)
};

TrimTargets exactTargets(const TrimSpec& spec);

// net_now_kg, pitch_now_rad, roll_now_rad: the vehicle before the move.
TrimTargets halfWayTargets(const TrimSpec& spec, double net_now_kg, double pitch_now_rad, double roll_now_rad);

// Distance of v outside [lo, hi] (0 inside).
inline double bandViolation(double v, double lo, double hi) {
  return v < lo ? lo - v : (v > hi ? v - hi : 0.0);
}

}  // namespace auv::ballast
