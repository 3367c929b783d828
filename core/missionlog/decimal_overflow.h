#pragma once
// Shared by the text readers: what an out-of-range number text means.
#include <string_view>

namespace auv {

// For a numeric text std::from_chars reported out of range: true when it
// overflowed (the value is huge: a fill value or corruption), false when it
// underflowed (the value is ~0 and can be kept as 0).
bool decimalOverflows(std::string_view s);

}  // namespace auv
