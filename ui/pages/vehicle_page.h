#pragma once
#include <QWizardPage>

#include "wizard/wizard_state.h"

class QComboBox;
class QLineEdit;
class QLabel;

namespace auv::ui {

// Pick the vehicle profile and name the configuration being ballasted.
class VehiclePage : public QWizardPage {
  Q_OBJECT
 public:
  explicit VehiclePage(WizardState& state);
  bool validatePage() override;
  int nextId() const override;

 private:
  void showProfile();
  WizardState& state_;
  QComboBox* vehicle_;
  QLineEdit* config_;
  QLineEdit* payload_;
  QLabel* summary_;
  QLabel* error_;
};

}  // namespace auv::ui
