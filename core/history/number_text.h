#pragma once
// Numbers in the text formats we write (ballasting file, CSV): the shortest
// text that reads back to the same double, so an export -> import round trip
// is exact and a human sees "19.2", not "19.199999999999999".
#include <optional>
#include <string>
#include <string_view>

namespace auv {

std::string formatShortest(double v);
// The whole text must be one finite number (C locale); nullopt otherwise.
std::optional<double> parseNumber(std::string_view text);

}  // namespace auv
