#include "missionlog/decimal_overflow.h"

namespace auv {

bool decimalOverflows(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  long intDigits = 0, leadingFracZeros = 0;
  bool nonzero = false;
  for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i)
    if (s[i] != '0' || nonzero) {
      nonzero = true;
      ++intDigits;
    }
  if (i < s.size() && s[i] == '.')
    for (++i; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i)
      if (!nonzero) {
        if (s[i] == '0') ++leadingFracZeros;
        else nonzero = true;
      }
  long exponent = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    long sign = 1;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) sign = s[i++] == '-' ? -1 : 1;
    for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i)
      if (exponent < 100000000) exponent = exponent * 10 + (s[i] - '0');
    exponent *= sign;
  }
  return (intDigits > 0 ? intDigits : -leadingFracZeros) + exponent > 0;
}

}  // namespace auv
