#include "wizard/operator_wizard.h"

#include "pages/crane_weighing_page.h"
#include "pages/first_mission_result_page.h"
#include "pages/vehicle_page.h"
#include "pages/water_page.h"

namespace auv::ui {

OperatorWizard::OperatorWizard(WizardState state, QWidget* parent) : QWizard(parent), state_(std::move(state)) {
  setWindowTitle(tr("auvballast - ballast wizard"));
  setWizardStyle(QWizard::ClassicStyle);
  setOption(QWizard::NoBackButtonOnStartPage);
  setPage(kVehicle, new VehiclePage(state_));
  setPage(kCraneWeighing, new CraneWeighingPage(state_));
  setPage(kWater, new WaterPage(state_));
  setPage(kFirstMissionResult, new FirstMissionResultPage(state_));
  setStartId(kVehicle);
  resize(1000, 720);
}

}  // namespace auv::ui
