#pragma once
// The few ASCII text helpers every missionlog parser needs. Log headers and
// cells are byte strings in an unknown 8-bit encoding, so these never touch
// bytes >= 0x80 and never depend on the C locale (std::tolower does).
#include <string>
#include <string_view>

namespace auv::detail {

// Without leading and trailing blanks and tabs.
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// A-Z lowered, every other byte kept.
inline std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

// Equal but for the case of A-Z.
inline bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

inline bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace auv::detail
