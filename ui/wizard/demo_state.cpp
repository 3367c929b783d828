#include "wizard/demo_state.h"

#include "firstmission/crane_weighing_file.h"
#include "vehicle/vehicle_catalog.h"

namespace auv::ui {

WizardState makeEmptyState(const std::string& resource_dir) {
  WizardState s;
  s.vehicles_dir = resource_dir + "/vehicles";
  s.crane.water = {10.0, 35.0, 0.0, 60.0};
  return s;
}

WizardState makeDemoState(const std::string& resource_dir) {
  WizardState s = makeEmptyState(resource_dir);
  const CraneWeighingFile f = loadCraneWeighingFile(resource_dir + "/examples/hugin1000_first_mission.json");
  s.vehicle = VehicleCatalog(s.vehicles_dir).load(f.vehicle);
  s.crane = f.input;
  s.configuration_id = "01-02-03";
  s.payload_note = "Demo: thesis whole-system test vehicle";
  return s;
}

}  // namespace auv::ui
