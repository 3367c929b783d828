#pragma once
// Masses inside the solver are whole multiples of 0.1 g so that sums of
// pieces compare exactly (3 x 1.2 kg is 3.6 kg, not 3.5999999999999996).
#include <cmath>
#include <cstdint>

namespace auv::ballast {

inline constexpr double kQuantumKg = 1e-4;

inline std::int64_t toQuanta(double kg) { return std::llround(kg / kQuantumKg); }
inline double toKg(std::int64_t q) { return static_cast<double>(q) * kQuantumKg; }

}  // namespace auv::ballast
