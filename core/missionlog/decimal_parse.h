#pragma once
// The number parser of the CSV fast path, in a header so that tests and the
// fuzzer can hold it against std::from_chars.
#include <charconv>
#include <cstdint>

namespace auv {

inline constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// Parses a number at p; returns the first character after it, or nullptr if
// there is none. Same acceptance and the same double as std::from_chars
// (chars_format::general). Plain decimals ("-12.345", "160") with at most 15
// digits take Clinger's fast path: the digits form an exact integer below
// 2^53 and 10^k (k <= 15) is exact, so one IEEE division is the correctly
// rounded result. Exponents, longer mantissas, nan/inf and garbage go to
// std::from_chars.
inline const char* parseDecimal(const char* p, const char* end, double& out) {
  const char* q = p;
  const bool negative = q < end && *q == '-';
  q += negative;
  std::uint64_t mantissa = 0;
  int digits = 0, fraction = 0;
  while (q < end && static_cast<unsigned>(*q - '0') < 10u) {
    mantissa = mantissa * 10 + static_cast<unsigned>(*q - '0');
    ++digits;
    ++q;
  }
  if (q < end && *q == '.') {
    ++q;
    while (q < end && static_cast<unsigned>(*q - '0') < 10u) {
      mantissa = mantissa * 10 + static_cast<unsigned>(*q - '0');
      ++digits;
      ++fraction;
      ++q;
    }
  }
  if (digits == 0 || digits > 15 || (q < end && (*q == 'e' || *q == 'E'))) {
    const auto r = std::from_chars(p, end, out);
    return r.ec == std::errc{} ? r.ptr : nullptr;
  }
  const double m = static_cast<double>(mantissa);
  out = fraction ? m / kPow10[fraction] : m;
  if (negative) out = -out;
  return q;
}

}  // namespace auv
