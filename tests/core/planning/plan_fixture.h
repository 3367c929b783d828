#pragma once
// Shared pieces of the planning tests: the HUGIN profile and an estimate as
// a post-mission analysis would report it.
#include <string>

#include "planning/pre_mission_plan.h"
#include "seawater/seawater.h"
#include "vehicle/vehicle_catalog.h"

namespace auv::planning_test {

inline VehicleProfile hugin() { return VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000"); }

inline TrimEstimate estimateAt(double net_kg, double x_mm, double y_mm, double t, double s, double depth_m,
                               double sigma_kg = 0.1, double sx_mm = 0.05, double sy_mm = 0.01) {
  TrimEstimate e;
  e.net_buoyancy_kg = net_kg;
  e.net_buoyancy_sigma_kg = sigma_kg;
  e.cg_x_m = x_mm / 1000.0;
  e.cg_y_m = y_mm / 1000.0;
  e.cg_x_sigma_m = sx_mm / 1000.0;
  e.cg_y_sigma_m = sy_mm / 1000.0;
  e.salinity_psu = s;
  e.depth_m = depth_m;
  e.water.temperature_degC = t;
  e.water.pressure_dbar = seawater::pressureFromDepth(depth_m);
  e.water.density_kgm3 = seawater::density(s, t, e.water.pressure_dbar);
  return e;
}

inline PlannedWater water(double t, double s, double depth_m) {
  PlannedWater w;
  w.temperature_degC = t;
  w.salinity_psu = s;
  w.depth_m = depth_m;
  return w;
}

}  // namespace auv::planning_test
