#include "history/records.h"

#include "common/input_error.h"

namespace auv {

const char* toString(WeighingMethod m) { return m == WeighingMethod::kTank ? "tank" : "crane"; }

WeighingMethod weighingMethodFromString(const std::string& s) {
  if (s == "crane") return WeighingMethod::kCrane;
  if (s == "tank") return WeighingMethod::kTank;
  throw InputError("weighing.method", "unknown method '" + s + "'", "use crane or tank");
}

}  // namespace auv
