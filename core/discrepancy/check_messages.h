#pragma once
// The model check's explanations (where a residual concentrates, what the
// model is) as message ids with English formats: the CLI and JSON print the
// English, the wizard translates by id (ui/wizard/advice_text.*). Word
// arguments (the error's name, factor names, steps, relations, phases) are
// short fixed English words the wizard translates one by one.
#include "common/message.h"

namespace auv::discrepancy::msg {

inline constexpr MessageFormat kConstant{"check.constant",
                                         "%1 is a constant %2 %3 everywhere (all phases, depths and speeds)"};
inline constexpr MessageFormat kGrows{"check.grows", "%1 grows %2 %3 per %4 (%5 %3, %6 % of its variance)"};
inline constexpr MessageFormat kShrinks{"check.shrinks", "%1 shrinks %2 %3 per %4 (%5 %3, %6 % of its variance)"};
inline constexpr MessageFormat kGrowsBeyond{"check.grows_beyond",
                                            "%1 grows %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % of its variance)"};
inline constexpr MessageFormat kShrinksBeyond{"check.shrinks_beyond",
                                              "%1 shrinks %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % of its variance)"};
inline constexpr MessageFormat kConcentrates{"check.concentrates",
                                             "%1 concentrates at %2 %3 (mean %4 %5 against %6 overall)"};
// Built in pieces: what, phase (plural), mean, unit, then (phase, mean) pairs
// of the other phases: "%1 is largest during %2: mean %3 %4 (climbs 1.2, ...)".
inline constexpr const char* kLargestDuring = "check.largest_during";
inline constexpr MessageFormat kNoFactor{"check.no_factor", "%1: no factor of the log explains it"};
// Built in pieces: the finding's id and arguments, then the factor the error
// does not depend on ("" when none): "<finding>; independent of %n".
inline constexpr const char* kSummary = "check.summary";

inline constexpr MessageFormat kModelAuv{
    "check.model_auv",
    "AUV rigid-body model of core/sim (Fossen form) on smoothed logged states; simulation: replay of the logged "
    "commands through the model's autopilot; ballast state: net buoyancy and CG x/y"};
inline constexpr MessageFormat kModelGlider{
    "check.model_glider",
    "steady glide (Merckelbach et al. 2010) on %1-derived vertical velocity; ballast state: net buoyancy at the "
    "mean operating state and Cd0"};
inline constexpr MessageFormat kModelGliderLift{
    "check.model_glider_lift",
    "steady glide (Merckelbach et al. 2010) on %1-derived vertical velocity; ballast state: net buoyancy at the "
    "mean operating state and Cd0, with the lift slope"};

}  // namespace auv::discrepancy::msg
