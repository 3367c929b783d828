#pragma once
#include <QWizardPage>

#include "wizard/wizard_state.h"

class QComboBox;
class QLabel;

namespace auv::ui {

class NumberInput;

// The water the next mission will fly in: temperature, salinity (typed, or a
// water type from the thesis's Table 2.1) and the planned operating depth.
class WaterPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit WaterPage(WizardState& state);
  void initializePage() override;
  // Back keeps what was typed (stored, not validated): nothing is lost going back and forth.
  void cleanupPage() override;
  bool validatePage() override;
  int nextId() const override;

 private:
  void updateDensity();
  WizardState& state_;
  NumberInput* temperature_;
  QComboBox* water_type_;
  NumberInput* salinity_;
  NumberInput* depth_;
  NumberInput* latitude_;
  QLabel* density_;
  QLabel* error_;
};

}  // namespace auv::ui
