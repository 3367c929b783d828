#pragma once
// The first mission's own advice as message ids (common/message.h): the CLI
// prints the English, the wizard translates by id (ui/wizard/advice_text.*).
// The ballast solver's notes and warnings keep their ballast.* ids.
#include "common/message.h"

namespace auv::firstmission::msg {

inline constexpr MessageFormat kCapsizeProfileBg{
    "first_mission.capsize", "CG is not below CB with the profile's bg_mm: the vehicle would capsize; check bg_mm"};

inline constexpr const MessageFormat* kAll[] = {&kCapsizeProfileBg};

}  // namespace auv::firstmission::msg
