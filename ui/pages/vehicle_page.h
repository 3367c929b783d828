#pragma once
#include <QWizardPage>

#include "wizard/wizard_state.h"

class QComboBox;
class QLineEdit;
class QLabel;

namespace auv::ui {
class NumberInput;

// Pick the vehicle profile and name the configuration being ballasted. A
// configuration taken from the history keeps its ID and vehicle (they
// identify it); a new one is checked against the history's ID rule. The
// profile's kind decides the weighing: crane pages for an AUV, tank pages
// for a glider.
class VehiclePage : public QWizardPage {
  Q_OBJECT
 public:
  explicit VehiclePage(WizardState& state);
  void initializePage() override;
  // Back keeps what was typed (stored, not validated): nothing is lost going back and forth.
  void cleanupPage() override;
  bool validatePage() override;
  int nextId() const override;

 private:
  void showProfile();
  void checkId();
  void storeBg();  // the BG field into the state (0 = not measured)
  WizardState& state_;
  QComboBox* vehicle_;
  QLineEdit* config_;
  QLineEdit* payload_;
  QLineEdit* area_;
  QLineEdit* water_type_;
  NumberInput* bg_;
  QLabel* bg_label_;
  QLabel* summary_;
  QLabel* id_hint_;
  QLabel* error_;
  std::string shown_kind_;  // kind of the profile in the combo
};

}  // namespace auv::ui
