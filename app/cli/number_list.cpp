#include "number_list.h"

#include <charconv>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"

namespace auv::cli {

double parseNumber(const std::string& raw, const std::string& field, const std::string& what) {
  std::string t = raw;
  while (!t.empty() && t.front() == ' ') t.erase(t.begin());
  while (!t.empty() && t.back() == ' ') t.pop_back();
  if (!t.empty() && t.front() == '+') t.erase(t.begin());
  double v = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) {
    throw InputError(field, "'" + raw + "' is not a number", "give " + what);
  }
  return v;
}

std::vector<double> parseNumberList(const std::string& text, std::size_t expected, const std::string& field,
                                    const std::string& what) {
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    out.push_back(parseNumber(text.substr(start, comma - start), field, what));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (expected != 0 && out.size() != expected) {
    throw InputError(field, "expected " + std::to_string(expected) + " comma-separated values, got " +
                                std::to_string(out.size()),
                     "give " + what);
  }
  return out;
}

double parseBgMm(const std::string& text) {
  const double bg = parseNumber(text, "bg-mm", "the CG-below-CB distance in mm from an inclining or roll test");
  if (!(bg > 0.0)) throw InputError("bg-mm", "must be positive (CG below CB)", "give the measured distance in mm, e.g. --bg-mm 20");
  return units::mmToM(bg);
}

}  // namespace auv::cli
