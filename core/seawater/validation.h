#pragma once
// Range checks shared by every seawater function. The check itself is inline
// and allocation-free (these functions run once per log sample); only the
// failure path builds a message, out of line.
//
// Ranges (inclusive) and why:
//   salinity_psu      0 .. 42      EOS-80 range; also the range PSS-78 returns
//   practical salinity 2 .. 42     PSS-78 definition range: salinity input of the
//                                  conductivity inverse (below S~0.008 the PSS-78
//                                  polynomial has no inverse at all)
//   temperature_degC -2 .. 40      EOS-80 / PSS-78 fit range (either scale)
//   pressure_dbar     0 .. 11000   sea (gauge) pressure; full-ocean depth
//   conductivity_Sm   0 .. 10      above S=42, T=40 degC, 11000 dbar (~8.5 S/m)
//   conductivity_ratio 0 .. 2.5    C / C(35,15,0), same bound as conductivity
//   latitude_deg    -90 .. 90
//   depth_m           0 .. 10600   deepest depth whose pressure stays within
//                                  11000 dbar at every latitude (UNESCO 1983)
// NaN and infinities fail every range.

namespace auv::seawater {

struct ValidRange {
  double min;
  double max;
  const char* unit;
};

inline constexpr ValidRange kSalinityRange{0.0, 42.0, "psu"};
inline constexpr ValidRange kPracticalSalinityRange{2.0, 42.0, "psu"};
inline constexpr ValidRange kTemperatureRange{-2.0, 40.0, "degC"};
inline constexpr ValidRange kPressureRange{0.0, 11000.0, "dbar"};
inline constexpr ValidRange kConductivityRange{0.0, 10.0, "S/m"};
inline constexpr ValidRange kConductivityRatioRange{0.0, 2.5, "(ratio)"};
inline constexpr ValidRange kLatitudeRange{-90.0, 90.0, "deg"};
inline constexpr ValidRange kDepthRange{0.0, 10600.0, "m"};

// Throws auv::InputError naming the field, the value and the valid range.
[[noreturn]] void throwOutOfRange(const char* field, double value, const ValidRange& range);

inline void requireInRange(const char* field, double value, const ValidRange& range) {
  // Written so that NaN (all comparisons false) lands in the throwing branch.
  if (!(value >= range.min && value <= range.max)) [[unlikely]] {
    throwOutOfRange(field, value, range);
  }
}

}  // namespace auv::seawater
