#include "vehicle/installed_check.h"

#include <cmath>
#include <sstream>

namespace auv {
namespace {
std::string kgText(double kg) {
  std::ostringstream s;
  s.precision(6);
  s << kg << " kg";
  return s.str();
}
}  // namespace

void checkInstalledKg(const VehicleProfile& v, std::span<const double> kg, const std::string& field,
                      const InputLocation& where) {
  std::string names;
  for (const auto& p : v.points) names += (names.empty() ? "" : ",") + p.name;
  if (kg.size() != v.points.size()) {
    throw InputError(field,
                     "has " + std::to_string(kg.size()) + " values but '" + v.id + "' has " +
                         std::to_string(v.points.size()) + " adjustment points",
                     "give one mass in kg per point, in this order: " + names, where);
  }
  for (std::size_t i = 0; i < kg.size(); ++i) {
    const AdjustmentPoint& p = v.points[i];
    if (!std::isfinite(kg[i]) || kg[i] < 0.0) {
      throw InputError(field, "mass at " + p.name + " (" + kgText(kg[i]) + ") is not a mass that can be installed",
                       "give the kg of adjustment weight at each point, 0 or more (" + names + ")", where);
    }
    if (kg[i] > p.capacity_kg + 1e-9) {
      throw InputError(field,
                       "mass at " + p.name + " (" + kgText(kg[i]) + ") is more than the point holds (capacity " +
                           kgText(p.capacity_kg) + ")",
                       "check the value (kg, not g?) and the point order " + names, where);
    }
  }
}

}  // namespace auv
