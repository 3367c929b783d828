#pragma once
// EOS-80 and PSS-78 were fitted on the IPTS-68 temperature scale, but every CTD
// built since 1990 reports ITS-90. The public API therefore takes ITS-90 and
// converts internally; the IPTS-68 path exists so the published UNESCO check
// values (all quoted in IPTS-68) can be reproduced digit for digit.
// See docs/decisions/seawater-temperature-scale.md.

namespace auv::seawater {

enum class TempScale { ITS90, IPTS68 };

// Saunders (1990) linear approximation, the one the UNESCO/CSIRO seawater
// libraries use; within 1 mK of the full conversion over -2..40 degC.
inline constexpr double kT68PerT90 = 1.00024;

inline constexpr double t68FromT90(double t90_degC) { return t90_degC * kT68PerT90; }
inline constexpr double t90FromT68(double t68_degC) { return t68_degC / kT68PerT90; }

inline constexpr double toT68(double temperature_degC, TempScale scale) {
  return scale == TempScale::ITS90 ? t68FromT90(temperature_degC) : temperature_degC;
}

}  // namespace auv::seawater
