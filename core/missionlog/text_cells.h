#pragma once
// Numeric cells of vendor text logs, shared by the delimited-text and Slocum
// readers: the interchange reader's number parser (decimal_parse.h) on the
// common case, then blanks, quotes, '+' signs, decimal commas and the many
// spellings of "not sampled".
#include <string_view>

namespace auv {

enum class CellValue {
  kNumber,  // `v` holds the value (may be +-inf after overflow; tidyTable blanks it)
  kEmpty,   // empty, NaN, NA, n/a, null, none, -, --, ***: not sampled
  kBad,     // not a number
};

// `decimalComma` also accepts one ',' as the decimal mark ("12,5").
CellValue parseNumberCell(std::string_view cell, bool decimalComma, double& v);

// True for the spellings parseNumberCell reads as kEmpty (cell already trimmed).
bool isMissingSpelling(std::string_view cell);

}  // namespace auv
