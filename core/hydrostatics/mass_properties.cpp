#include "hydrostatics/mass_properties.h"

#include "common/input_error.h"

namespace auv {

MassProperties& MassProperties::add(const MassItem& item) {
  mass_kg += item.mass_kg;
  moment_kgm += item.mass_kg * item.position_m;
  if (mass_kg > 0.0) cg_m = moment_kgm / mass_kg;
  return *this;
}

MassProperties massProperties(std::span<const MassItem> items) {
  MassProperties mp;
  for (const auto& it : items) mp.add(it);
  if (!(mp.mass_kg > 0.0)) {
    throw InputError("mass", "total mass is not positive", "check the masses entered");
  }
  return mp;
}

}  // namespace auv
