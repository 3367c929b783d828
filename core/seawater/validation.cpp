#include "seawater/validation.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/input_error.h"

namespace auv::seawater {
namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

void throwOutOfRange(const char* field, double value, const ValidRange& range) {
  const std::string span = number(range.min) + " .. " + number(range.max) + " " + range.unit;
  const std::string problem = std::isnan(value)
                                  ? std::string("is not a number (valid range ") + span + ")"
                                  : number(value) + " is outside the valid range " + span;
  throw InputError(field, problem, "give a value within " + span);
}

}  // namespace auv::seawater
