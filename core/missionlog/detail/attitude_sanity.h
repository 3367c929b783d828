#pragma once
// Attitude columns whose unit is probably wrong, shared by every reader (the
// vendor-text table tidier and the interchange CSV): a pitch beyond +-90 deg
// or a roll beyond +-180 deg cannot be an attitude (degrees declared as
// radians), and a dived log whose pitch never leaves +-1.6 "deg" is almost
// certainly radians declared as degrees.
#include <cstddef>
#include <string_view>
#include <vector>

namespace auv::detail {

struct AttitudeCheck {
  double limit_deg = 0.0;       // 90.5 (pitch), 180.5 (roll); 0 = not an attitude channel
  std::size_t valid = 0;        // finite values looked at
  std::size_t beyond = 0;       // of them beyond the limit (now NaN)
  std::size_t first_beyond = 0; // index of the first
  double worst_deg = 0.0;       // largest |value| beyond the limit
  double max_abs_deg = 0.0;     // largest |value| within it
  bool mostlyBeyond() const { return 2 * beyond > valid; }
};

// `deg` holds the column after conversion to degrees; values beyond the limit
// are set to NaN (not sampled). `base` is the channel's base name.
AttitudeCheck checkAttitudeDeg(std::string_view base, std::vector<double>& deg);

// True when at least 10 values, all within +-1.6 (pitch) or +-3.2 (roll) deg,
// some non-zero, while the vehicle changed depth by more than `depth_span_m`
// >= 5 m: a dive needs more pitch than that, so the column is likely radians.
bool looksLikeRadians(std::string_view base, const AttitudeCheck& c, double depth_span_m);

}  // namespace auv::detail
