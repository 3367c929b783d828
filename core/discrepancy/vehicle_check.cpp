#include "discrepancy/vehicle_check.h"

#include "sim/mission_plan.h"

namespace auv::discrepancy {

std::unique_ptr<CheckModel> makeCheckModel(const MissionLog& log, const VehicleProfile& v, const std::string& resource_dir,
                                           const CheckSetup& s) {
  if (v.kind == "glider") return std::make_unique<GliderCheckModel>(log, v, s.glider);
  const sim::SimVehicle sv = sim::loadSimVehicle(v, resource_dir);
  return std::make_unique<AuvCheckModel>(log, v, sv.model, sv.autopilot, s.auv);
}

}  // namespace auv::discrepancy
