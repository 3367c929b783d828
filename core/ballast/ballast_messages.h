#pragma once
// The ballast solver's warnings as message ids (common/message.h): the CLI
// prints the English, the wizard translates by id (ui/wizard/advice_text.*).
#include "common/message.h"

namespace auv::ballast::msg {

// A band the kit cannot reach; the English is built in pieces. Arguments:
// band ("net buoyancy", "pitch", "roll"), the band's low end (net, kg text)
// or its tolerance (pitch/roll, deg text), its high end (net) or "", the best
// value, what an extra piece would do ("", "out_of_reach", "piece",
// "none_tried", "none_tried_undecided"), that piece's size or the sizes
// tried, "pitch_ok" when roll was missed keeping pitch in band; for pitch the
// plan appends the flight: speed m/s, pitch in flight deg, "inside"/"outside".
inline constexpr const char* kBandUnreachableId = "ballast.band_unreachable";
inline constexpr MessageFormat kStaysHeavy{
    "ballast.stays_heavy",
    "the vehicle stays %1 heavy even with every removable piece out; it needs added buoyancy or a lighter payload"};
inline constexpr MessageFormat kNodeLimit{
    "ballast.node_limit", "the search stopped at its node limit: this is the best move found, not a proved optimum"};
inline constexpr MessageFormat kCapsize{"ballast.capsize",
                                        "CG is not below CB after the move: the vehicle would capsize; check bg and payload"};
inline constexpr MessageFormat kThesisHeavy{"ballast.thesis_heavy", "the thesis mapping leaves the vehicle %1 heavy"};

// What to do at one point. kPoint is built in pieces: the point's name, the
// signed change, mass before, after, capacity, how many of the pieces are
// removals, then the pieces ("2 × 4.8 kg"), removals first.
inline constexpr MessageFormat kPointNoChange{"ballast.point_no_change", "%1: no change (%2 stays)."};
inline constexpr const char* kPointId = "ballast.point";
inline constexpr MessageFormat kPriorities{
    "ballast.priorities",
    "Priorities (thesis \u00a75.4): net buoyancy %1 to %2 and never negative, then pitch within \u00b1%3, then roll "
    "within \u00b1%4; %5 piece(s) to handle."};
inline constexpr MessageFormat kAfterMove{"ballast.after_move", "After the move: net buoyancy %1, pitch %2, roll %3."};
inline constexpr MessageFormat kHalfWay{
    "ballast.half_way",
    "HalfWay policy: this move aims at about half of the needed change (net buoyancy %1 to %2, pitch %3, roll %4); "
    "check the vehicle again and repeat."};

inline constexpr const MessageFormat* kAll[] = {&kStaysHeavy, &kNodeLimit,  &kCapsize,  &kThesisHeavy,
                                                &kPointNoChange, &kPriorities, &kAfterMove, &kHalfWay};

}  // namespace auv::ballast::msg
