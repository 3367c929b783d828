#pragma once
// The vehicle as the last mission showed it. The analysis measured net
// buoyancy in the log's water, so the mass is
//   m = rho_log V(T_log, p_log) - net_log
// (the hull volume law from the profile, or from accepted model terms), and
// the CG is CB + the identified offset in x and y, with z from the BG the
// analysis used (the roll test's when measured, else the profile's: a
// level-flight log cannot see CG height). Its buoyancy elsewhere is
// rho V(T, p) of that water: nothing measured in one water is carried to
// another as a net buoyancy.
#include <Eigen/Core>
#include <vector>

#include "hydrostatics/mass_properties.h"
#include "planning/next_mission_water.h"
#include "planning/trim_estimate.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

struct EstimatedVehicle {
  MassProperties mass;              // installed pieces included
  double mass_sigma_kg = 0.0;       // = the net buoyancy's sigma (the volume law is taken as known)
  Eigen::Vector3d cb_m = Eigen::Vector3d::Zero();
  double log_displaced_kg = 0.0;    // rho_log V(T_log, p_log)
  bool cg_x_assumed = false, cg_y_assumed = false;  // not identified: taken at the CB (no change asked)
};

// Throws InputError if the estimate is not physical (non-positive mass,
// non-finite values, negative sigmas), naming the field.
EstimatedVehicle estimatedVehicle(const VehicleProfile& v, const HullModel& hull, const TrimEstimate& e);

// Density, temperature and pressure of a planned point, and rho V there.
ResolvedPoint resolvePoint(const HullModel& hull, const PlannedWater& w);

// 1-sigma of rho V at a planned point from the operator's temperature and
// salinity uncertainty (EOS-80 derivatives by central differences).
double displacedSigmaKg(const HullModel& hull, const PlannedWater& w, double temperature_sigma_degC,
                        double salinity_sigma_psu);

// 1-sigma of the buoyancy change from the log's water to the planned point
// that the uncertainty of a fitted hull law leaves (the analysis's sigmas of
// the compressibility and the thermal expansion; 0 for a law not fitted).
// The two are added in quadrature: the report carries their sigmas, not
// their correlation.
double hullLawSigmaKg(const HullModel& hull, const WaterState& log_water, const PlannedWater& w,
                      double compressibility_sigma_per_dbar, double thermal_expansion_sigma_per_degC);

}  // namespace auv
