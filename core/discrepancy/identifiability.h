#pragma once
// What extra manoeuvre would separate two effects that a log cannot tell
// apart. Known pairs carry the physical reason; any other pair is answered
// from the terms' own excitation notes (physics_terms.cpp).
#include <string>
#include <string_view>

namespace auv::discrepancy {

// `a`, `b`: term ids, or "ballast_state" for the always-estimated net
// buoyancy / CG / drag.
std::string separationAdvice(std::string_view a, std::string_view b);

}  // namespace auv::discrepancy
