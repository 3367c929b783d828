#include "hydrostatics/balance.h"

#include "common/units.h"

namespace auv {

double displacedMassKg(const HullModel& hull, const WaterState& water) {
  return water.density_kgm3 * hull.volumeAt(water.temperature_degC, water.pressure_dbar);
}

Balance computeBalance(const MassProperties& mass, const HullModel& hull,
                       const Eigen::Vector3d& cb_m, const WaterState& water) {
  Balance b;
  b.mass_kg = mass.mass_kg;
  b.cg_m = mass.cg_m;
  b.cb_m = cb_m;
  b.buoyancy_kg = displacedMassKg(hull, water);
  b.net_buoyancy_kg = b.buoyancy_kg - b.mass_kg;
  b.trim = staticTrim(units::g0 * b.mass_kg, units::g0 * b.buoyancy_kg, b.cg_m, b.cb_m);
  return b;
}

}  // namespace auv
