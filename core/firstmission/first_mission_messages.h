#pragma once
// The first mission's own advice as message ids (common/message.h): the CLI
// prints the English, the wizard translates by id (ui/wizard/advice_text.*).
// The ballast solver's notes and warnings keep their ballast.* ids.
#include "common/message.h"

namespace auv::firstmission::msg {

inline constexpr MessageFormat kCapsizeProfileBg{
    "first_mission.capsize", "CG is not below CB with the profile's bg_mm: the vehicle would capsize; check bg_mm"};

// The Slocum tank weighing and roll test (core/firstmission/slocum_first_mission.cpp).
// Word arguments: sides ("starboard", "port"), directions ("port to the
// starboard", "lower to the upper", ...), "lowers"/"raises".
inline constexpr MessageFormat kTankDisplaces{
    "first_mission.tank_displaces",
    "In the tank (%1, %2) the glider displaces %3 (%4); at %5 the hull measures %6, neutral at %7 in %8 water."};
inline constexpr MessageFormat kWeighsLight{
    "first_mission.weighs_light",
    "It weighs %1, so it is %2 light: the bottles change by %3 (rounded down to whole grams so it never ends heavy)."};
inline constexpr MessageFormat kWeighsHeavy{
    "first_mission.weighs_heavy",
    "It weighs %1, so it is %2 heavy: the bottles change by %3 (rounded down to whole grams so it never ends heavy)."};
inline constexpr MessageFormat kBowBottles{
    "first_mission.bow_bottles",
    "Bow bottles: %1 in %2 and %3 in %4 (%5) so the bow scale would read %6 and the glider floats level."};
inline constexpr MessageFormat kAftBottles{
    "first_mission.aft_bottles",
    "Aft bottles: %1 in %2 and %3 in %4 (%5) so the aft scale would read %6 and the glider floats level."};
inline constexpr MessageFormat kNoRollTest{
    "first_mission.no_roll_test",
    "No roll test recorded: set the bottles, hang the glider for the roll test (report 4.2) and run again with "
    "after_tank_step_g and roll_test filled in; CG height is the profile's bg_mm."};
inline constexpr MessageFormat kRollTest{"first_mission.roll_test",
                                         "Roll test: h = %1 from %2 hung masses, so G sits %3 to %4 of B and %5 below it."};
inline constexpr MessageFormat kMoveRail{
    "first_mission.move_rail",
    "Move %1 of rail weight from the %2 wing rail, because the battery alone cannot reach the roll."};
inline constexpr MessageFormat kMoveBowBottle{
    "first_mission.move_bow_bottle", "Move %1 of lead from the %2 bow bottle, because the battery cannot reach the roll."};
inline constexpr MessageFormat kMoveBowBottleRails{
    "first_mission.move_bow_bottle_rails",
    "Move %1 of lead from the %2 bow bottle, because the battery and wing rails cannot reach the roll."};
inline constexpr MessageFormat kRollBattery{
    "first_mission.roll_battery", "Set the roll battery to %1 (%2, toward %3, now %4) to bring G straight below B."};
inline constexpr MessageFormat kRollRemains{
    "first_mission.roll_remains",
    "the battery, wing rails and bow bottles together cannot cancel the roll: %1 remains; move other masses sideways"};
inline constexpr MessageFormat kSwapDisks{"first_mission.swap_disks",
                                          "Swap disk column %1 (%2 top, %3 bottom), which %4 G by %5."};
inline constexpr MessageFormat kMoveAftBottle{
    "first_mission.move_aft_bottle", "Move %1 of lead from the %2 aft bottle, so h goes from %3 to %4 (target %5)."};
inline constexpr MessageFormat kHArmUnreachable{
    "first_mission.h_arm_unreachable",
    "the h-arm target %1 is not reachable with the disk weights and aft bottles; best is %2 (arrangement %3)"};
inline constexpr MessageFormat kEndsHeavy{"first_mission.ends_heavy",
                                          "predicted net buoyancy %1 is below the profile's band: the glider would end HEAVY"};
inline constexpr MessageFormat kAboveBand{"first_mission.above_band", "predicted net buoyancy %1 is above the profile's band"};
inline constexpr MessageFormat kPitchOutside{"first_mission.pitch_outside", "predicted pitch %1 is outside +-%2"};
inline constexpr MessageFormat kRollOutside{"first_mission.roll_outside", "predicted roll %1 is outside +-%2"};

inline constexpr const MessageFormat* kAll[] = {
    &kCapsizeProfileBg, &kTankDisplaces, &kWeighsLight,     &kWeighsHeavy,  &kBowBottles,      &kAftBottles,
    &kNoRollTest,       &kRollTest,      &kMoveRail,        &kMoveBowBottle, &kMoveBowBottleRails, &kRollBattery,
    &kRollRemains,      &kSwapDisks,     &kMoveAftBottle,   &kHArmUnreachable, &kEndsHeavy,    &kAboveBand,
    &kPitchOutside,     &kRollOutside};

}  // namespace auv::firstmission::msg
