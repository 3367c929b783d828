#pragma once
// ISO 8601 / RFC 3339 timestamps as used by the interchange format
// (`# start: 2026-05-14T08:12:00Z`, `time [iso8601]`). A timestamp without a
// zone designator is read as UTC, which is what every glider and AUV logger we
// know writes; the reader says so in its report.
#include <optional>
#include <string>
#include <string_view>

namespace auv {

// Seconds since 1970-01-01T00:00:00Z. Accepts YYYY-MM-DD, optionally followed
// by 'T' or ' ' and hh:mm[:ss[.fraction]], optionally 'Z' or +hh[:mm] / -hh[:mm].
// nullopt for anything else (including out-of-range fields such as month 13).
std::optional<double> parseIso8601(std::string_view text);

// Parses a timestamp at the start of [begin, end); returns the first character
// after it, or nullptr if there is no valid timestamp there. `hadZone` tells
// whether a zone designator was present. Allocation-free for the CSV fast path.
const char* parseIso8601Prefix(const char* begin, const char* end, double& epochSeconds,
                               bool& hadZone);

// "2026-05-14T08:12:00.000Z" with `fractionDigits` digits (0..9) after the seconds.
std::string formatIso8601(double epochSeconds, int fractionDigits = 3);

}  // namespace auv
