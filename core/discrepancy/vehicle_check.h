#pragma once
// The right check model for a vehicle: the steady-glide model for a glider
// profile, the simulator's rigid-body model (its profile's sim sections or
// <resource_dir>/sim/<id>_hydrodynamics.json) for an AUV.
#include <memory>
#include <string>

#include "discrepancy/auv_check_model.h"
#include "discrepancy/glider_check_model.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::discrepancy {

struct CheckSetup {
  GliderCheckOptions glider;
  AuvCheckOptions auv;
};

// Throws InputError when the log lacks what the vehicle's model needs.
std::unique_ptr<CheckModel> makeCheckModel(const MissionLog& log, const VehicleProfile& v, const std::string& resource_dir,
                                           const CheckSetup& setup = {});

}  // namespace auv::discrepancy
