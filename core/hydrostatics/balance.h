#pragma once
// The weight/buoyancy balance of a vehicle at given water density: what the
// first-mission report and the ballast solver both present.
#include <Eigen/Core>

#include "hydrostatics/mass_properties.h"
#include "hydrostatics/static_trim.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

struct WaterState {
  double density_kgm3 = 1025.0;  // in situ
  double temperature_degC = 10.0;
  double pressure_dbar = 0.0;
};

struct Balance {
  double mass_kg = 0.0;
  double buoyancy_kg = 0.0;      // displaced mass rho * V(T, p)
  double net_buoyancy_kg = 0.0;  // buoyancy - mass; positive = too light
  Eigen::Vector3d cg_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d cb_m = Eigen::Vector3d::Zero();
  StaticTrim trim;
};

// Displaced mass of the hull in the given water.
double displacedMassKg(const HullModel& hull, const WaterState& water);

Balance computeBalance(const MassProperties& mass, const HullModel& hull,
                       const Eigen::Vector3d& cb_m, const WaterState& water);

}  // namespace auv
