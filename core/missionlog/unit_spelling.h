#pragma once
// Unit spellings as vendors write them ("degc", "S m-1", "nodim", "DEG",
// "kg m-3") mapped to the spellings unit_conversion knows, so that every
// reader converts through the one table in unit_conversion.cpp.
#include <string>
#include <string_view>

namespace auv {

// The known spelling of `unit` when one matches (exactly, through the alias
// list, or ignoring case), otherwise `unit` trimmed and unchanged, so that an
// unknown unit still reaches the error message as written.
std::string normaliseUnitSpelling(std::string_view unit);

}  // namespace auv
