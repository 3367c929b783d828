#pragma once
#include <QWizardPage>
#include <array>

#include "weighing/slocum_layout.h"
#include "wizard/wizard_state.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace auv::ui {

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
  QDoubleSpinBox* dry_mass_;
  QDoubleSpinBox* bow_scale_;
  QDoubleSpinBox* aft_scale_;
  QComboBox* tank_water_;
  QDoubleSpinBox* tank_density_;
  QDoubleSpinBox* tank_temperature_;
  QDoubleSpinBox* target_density_;
  QDoubleSpinBox* target_temperature_;
  std::array<QDoubleSpinBox*, kSlocumItemCount> ballast_{};
  QLabel* result_;
  QLabel* error_;
  bool ok_ = false;
  bool loading_ = false;
};

}  // namespace auv::ui
