#pragma once
#include <QWizardPage>
#include <array>

#include "weighing/slocum_layout.h"
#include "wizard/wizard_state.h"

class QComboBox;
class QLabel;
class QLineEdit;

namespace auv::ui {

class NumberInput;

// Slocum tank method (Baird 2007 §4.1): dry mass, the two spring scales over
// the bow and aft bottles with the glider submerged, the tank water and the
// deployment (target) water, and the lead now in the bottles and rails. The
// tank-step result (bottle changes, expected scale readings) is recomputed by
// core while typing, so a mistyped reading shows at once.
class TankWeighingPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit TankWeighingPage(WizardState& state);
  void initializePage() override;
  // Back keeps what was typed (stored, not validated): nothing is lost going back and forth.
  void cleanupPage() override;
  bool validatePage() override;
  bool isComplete() const override;
  int nextId() const override;

 private:
  void store(TankWeighing& w) const;
  void updatePreview();
  void applyWaterChoice();
  WizardState& state_;
  QLineEdit* glider_;
  NumberInput* dry_mass_;
  NumberInput* bow_scale_;
  NumberInput* aft_scale_;
  QComboBox* tank_water_;
  NumberInput* tank_density_;
  NumberInput* tank_temperature_;
  NumberInput* target_density_;
  NumberInput* target_temperature_;
  std::array<NumberInput*, kSlocumItemCount> ballast_{};
  QLabel* result_;
  QLabel* error_;
  bool ok_ = false;
  bool loading_ = false;
};

}  // namespace auv::ui
