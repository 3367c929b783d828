#pragma once
#include <QWizard>

#include "wizard/wizard_state.h"

namespace auv::ui {

// The guided sequence a technician follows on the dockside. Pages are added
// as the core they present lands: vehicle -> weighing -> water -> result.
class OperatorWizard : public QWizard {
  Q_OBJECT
 public:
  enum PageId { kVehicle = 0, kCraneWeighing, kWater, kFirstMissionResult };

  explicit OperatorWizard(WizardState state, QWidget* parent = nullptr);
  WizardState& state() { return state_; }

 private:
  WizardState state_;
};

}  // namespace auv::ui
