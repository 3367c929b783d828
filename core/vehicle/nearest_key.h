#pragma once
// The known key closest to a misspelt one, for "did you mean ...?" hints.
#include <string>
#include <string_view>
#include <vector>

namespace auv {

// Edit distance (insert, delete, substitute, swap of neighbours) between two keys.
std::size_t keyDistance(std::string_view a, std::string_view b);

// The nearest of `known` to `key`, or "" when nothing is close enough to be a
// plausible typo (distance above a third of the key's length, at least 2).
std::string nearestKey(std::string_view key, const std::vector<std::string>& known);

}  // namespace auv
