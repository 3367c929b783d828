#pragma once
#include <QWizardPage>
#include <array>

#include "wizard/wizard_state.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace auv::ui {

class NumberInput;

// Slocum roll test (Baird 2007 §4.2): with the bottles set after the tank
// step, the wingless glider hangs from nose hook and tail loop; the roll
// sensor is read with nothing hung and with each known mass on a wing rail.
// Core turns the readings into the h-arm and the G offset, which are shown
// while typing, with the field named when a reading cannot be right (e.g. a
// mass on the port rail that rolled the glider to starboard).
class RollTestPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit RollTestPage(WizardState& state);
  void initializePage() override;
  // Back keeps what was typed (stored, not validated): nothing is lost going back and forth.
  void cleanupPage() override;
  bool validatePage() override;
  bool isComplete() const override;
  int nextId() const override;

  int rowCount() const;
  void addRow(double mass_kg, bool starboard, double roll_rad);

 private:
  void store(TankWeighing& w) const;
  void updatePreview();
  void fillRecommended();
  WizardState& state_;
  QCheckBox* after_step_;
  std::array<NumberInput*, 4> after_{};
  QPushButton* use_recommended_;
  QCheckBox* roll_done_;
  NumberInput* initial_roll_;
  NumberInput* lever_arm_;
  QTableWidget* table_;
  QPushButton* add_row_;
  QPushButton* remove_row_;
  std::array<NumberInput*, 6> disks_{};  // A top, A bottom, B top, ...
  NumberInput* battery_angle_;
  QLabel* result_;
  QLabel* error_;
  bool ok_ = false;
  bool loading_ = false;
};

}  // namespace auv::ui
