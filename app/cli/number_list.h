#pragma once
// Comma-separated numeric flags ("374.5,374.5,380,370"): parsed here so the
// error names the flag, the bad item and what a valid value looks like.
#include <string>
#include <vector>

namespace auv::cli {

std::vector<double> parseNumberList(const std::string& text, std::size_t expected, const std::string& field,
                                    const std::string& what);
double parseNumber(const std::string& text, const std::string& field, const std::string& what);
// --bg-mm: the CG-below-CB distance of an inclining or roll test, mm -> m.
double parseBgMm(const std::string& text);

}  // namespace auv::cli
