#pragma once
// The weighing checks' warnings as message ids (common/message.h): the CLI
// prints the English, the wizard translates by id (ui/wizard/advice_text.*).
#include "common/message.h"

namespace auv::weighing::msg {

// Crane (crane_weighing.cpp): the parts do not add up to the hook.
inline constexpr MessageFormat kSumMismatch{
    "weighing.sum_mismatch",
    "the four readings add up to %1, total is %2 (tolerance %3); CG uses the parts, mass uses the total"};
// Roll test (roll_test.cpp).
inline constexpr MessageFormat kRollTestHLarge{
    "weighing.roll_test_h_large",
    "h = %1 is implausibly large for a glider (about 6 mm expected): check the roll signs and which rail the mass hung on"};
inline constexpr MessageFormat kRollTestSpread{"weighing.roll_test_spread",
                                               "the single h values spread by %1 (%2 of the mean): repeat the test"};
// Tank bottle split (tank_weighing.cpp).
inline constexpr MessageFormat kBottlesNotLevel{
    "weighing.bottles_not_level",
    "the bottles cannot hold the level split (bow %1, aft %2); the glider will not float level: move a disk or rail weight"};
inline constexpr MessageFormat kBottlesFull{
    "weighing.bottles_full",
    "the bottles are full: %1 more is needed for neutral; the glider stays light (add ballast elsewhere)"};
inline constexpr MessageFormat kBottlesEmpty{
    "weighing.bottles_empty",
    "the bottles are empty: %1 more must come out; the glider stays HEAVY: remove a disk or rail weight"};

inline constexpr const MessageFormat* kAll[] = {&kSumMismatch,     &kRollTestHLarge, &kRollTestSpread,
                                                &kBottlesNotLevel, &kBottlesFull,    &kBottlesEmpty};

}  // namespace auv::weighing::msg
