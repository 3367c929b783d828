#pragma once
// The pre-mission plan's advice (notes, warnings, explanations) as message
// ids with English formats: the CLI prints the English, the wizard
// translates by id (ui/wizard/advice_text.*). Words passed as arguments
// ("operating", "lighter") are translated there one by one.
#include "common/message.h"

namespace auv::planning::msg {

// One changed point; built in full by explainPlan (its English varies in
// several places), with arguments: label, pieces removed ("1 × 2.4 kg and
// ..." or ""), pieces added, signed kg, |kg|, CG shift x mm (+ forward), y mm
// (+ starboard), "lowers"/"raises", the dominant axis "x"/"y", and "back"
// (towards the CB) or "balanced" (by the other points).
inline constexpr const char* kExplainPointId = "plan.explain_point";
inline constexpr MessageFormat kNoChange{"plan.no_change", "No change: the vehicle is already as good as the kit allows."};
inline constexpr MessageFormat kNextMission{
    "plan.next_mission",
    "Next mission at %1: from net buoyancy %2, pitch %3, roll %4 to %5 \u00b1 %6, pitch %7 \u00b1 %8, roll %9 \u00b1 %10 "
    "(1 sigma)."};
inline constexpr MessageFormat kMassFromLastMission{
    "plan.mass_from_last_mission",
    "Mass %1 from the last mission: %2 displaced at %3, %4, %5 minus the measured net buoyancy %6."};
inline constexpr MessageFormat kSafetyMargin{
    "plan.safety_margin",
    "Safety margin %1 = %2 \u00d7 sigma %3 (estimate and water); the move keeps at least that much net buoyancy at "
    "every planned point."};
inline constexpr MessageFormat kCgXAssumed{
    "plan.cg_x_assumed",
    "CG x was not identified from the log: the plan assumes it at the CB and keeps the fore-aft balance; check pitch "
    "on the next mission"};
inline constexpr MessageFormat kCgYAssumed{
    "plan.cg_y_assumed",
    "CG y was not identified from the log: the plan assumes it at the CB and keeps the side balance; check roll on "
    "the next mission"};
inline constexpr MessageFormat kUnsafe{
    "plan.unsafe",
    "UNSAFE: at the %1 point (%2) the vehicle would have %3 net buoyancy, less than the safety margin %4"};
inline constexpr MessageFormat kUnsafeSinks{
    "plan.unsafe_sinks",
    "UNSAFE: at the %1 point (%2) the vehicle would have %3 net buoyancy, less than the safety margin %4: it would "
    "sink if it lost power there"};
inline constexpr MessageFormat kAboveBandForMargin{
    "plan.above_band_for_margin",
    "net buoyancy %1 at the operating depth is above the band %2 because the safety margin (%3) and the less buoyant "
    "planned points (%4 less) come first"};
inline constexpr MessageFormat kBandNotReachable{
    "plan.band_not_reachable",
    "net buoyancy band not reachable with this kit while keeping the safety margin: no combination of pieces lands "
    "between %1 and %2; the nearest safe one is %3"};
inline constexpr MessageFormat kOptionalPieces{
    "plan.optional_pieces",
    "The kit has optional pieces (%1) not used in this plan; enabling them (--optional-pieces) may reach the missed "
    "band."};
inline constexpr MessageFormat kWideSigma{
    "plan.wide_sigma",
    "The estimate's own uncertainty (pitch %1, roll %2) is wider than a tolerance band; the next mission will tell."};
inline constexpr MessageFormat kClassicTable{
    "plan.classic_table",
    "Classic table (thesis App. E): %1, pitch error %2, roll error %3; it moves one %4 piece per point and mission, "
    "whatever the size of the error."};
inline constexpr MessageFormat kClassicBlocked{
    "plan.classic_blocked", "the classic table asks to remove a piece where none is installed, so it changes nothing"};
inline constexpr MessageFormat kClassicStandardKit{"plan.classic_standard_kit",
                                                   "The classic table uses the standard kit only."};
inline constexpr MessageFormat kManoeuvre{
    "plan.manoeuvre",
    "the net-buoyancy sigma (%1 kg) is too wide for the %2 kg band: add the calibration manoeuvre to the next "
    "mission (%3 short leg(s)); with this log alone it would bring the sigma to about %4 kg"};
inline constexpr MessageFormat kAfterMove{
    "plan.after_move",
    "this move is also a calibration: flown after it and analysed with the last log as history (the known change of "
    "mass and moment between them), the next mission's survey should tell the net buoyancy to about +-%1 kg and CG x "
    "to about +-%2 mm, enough for a second move into the band"};
inline constexpr MessageFormat kAfterMoveStillWide{
    "plan.after_move_still_wide",
    "this move is also a calibration, but flown after it and analysed with the last log as history the next "
    "mission's survey would still leave the net buoyancy at about +-%1 kg (CG x about +-%2 mm), too wide for the band: "
    "fly the calibration manoeuvre as well"};
inline constexpr MessageFormat kRollAtCruise{
    "plan.roll_at_cruise",
    "roll is planned and predicted at cruise (%1 rpm, propeller torque included): the side balance that levels the "
    "vehicle there, as the thesis judges roll (\u00a75.3.3)"};

// Every plan message with a format, for completeness checks of the translations.
inline constexpr MessageFormat kLogNotAsCommanded{
    "plan.log_not_as_commanded",
    "the analysed log was not flown as commanded (%1; see its warnings), so this move rests on a net buoyancy sigma of "
    "%2 kg: after the move make a short test dive at the survey's speeds before the survey"};
inline constexpr const MessageFormat* kAll[] = {
    &kNoChange, &kNextMission, &kMassFromLastMission, &kSafetyMargin, &kCgXAssumed, &kCgYAssumed, &kUnsafe,
    &kUnsafeSinks, &kAboveBandForMargin, &kBandNotReachable, &kOptionalPieces, &kWideSigma, &kClassicTable,
    &kClassicBlocked, &kClassicStandardKit, &kManoeuvre, &kAfterMove, &kAfterMoveStillWide, &kRollAtCruise,
    &kLogNotAsCommanded};

}  // namespace auv::planning::msg
