#pragma once
// The glider plan's warnings and "cannot tell" lines as message ids
// (common/message.h). The plan is JSON: "warnings" and "cannot_tell" keep the
// English; "warnings_ids" and "cannot_tell_ids" beside them hold {id, args} at
// the same index (id "" for a line without one), which the wizard translates
// (ui/wizard/advice_text.*).
#include <nlohmann/json.hpp>

#include "common/message.h"

namespace auv::planning::msg {

inline constexpr MessageFormat kContentsUnknown{
    "glider_plan.contents_unknown",
    "bottle contents not given: capacities checked against half-full bottles (give what is in the bottles to check "
    "them)"};
inline constexpr MessageFormat kRailsShort{
    "glider_plan.rails_short",
    "the wing rails cannot take the whole roll correction (%1 g); move the roll battery or a disk weight for the rest"};
inline constexpr MessageFormat kNoPitchTrim{
    "glider_plan.no_pitch_trim",
    "the pitch trim (the log has no battery_position, or too little variation): the bottle split is Baird's level "
    "split only"};
inline constexpr MessageFormat kNoRoll{"glider_plan.no_roll", "roll (the log has no roll in glides)"};
inline constexpr MessageFormat kNoCPitch{"glider_plan.no_c_pitch",
                                         "C_PITCH (the log has no pitch-mass position with enough variation)"};
inline constexpr MessageFormat kNoGeometry{
    "glider_plan.no_geometry",
    "where the grams go: the log carries no ballast-place geometry; add %1 g at the vehicle's ballast places so that "
    "it stays level"};
inline constexpr MessageFormat kNoZeroOffset{
    "glider_plan.no_zero_offset",
    "the ballast (pump) zero offset in the vendor's setting: only the mass change is known"};

inline constexpr const MessageFormat* kGliderAll[] = {&kContentsUnknown, &kRailsShort, &kNoPitchTrim, &kNoRoll,
                                                      &kNoCPitch,        &kNoGeometry, &kNoZeroOffset};

// Appends `m` to plan[list] (English) and plan[list + "_ids"] ({id, args}).
inline void addPlanLine(nlohmann::json& plan, const std::string& list, const Message& m) {
  plan[list].push_back(m.text());
  plan[list + "_ids"].push_back({{"id", m.id()}, {"args", m.args()}});
}

}  // namespace auv::planning::msg
