#pragma once
#include <QWizardPage>
#include <array>

#include "wizard/wizard_state.h"

class QLabel;

namespace auv::ui {

class NumberInput;

class CraneSideView;

// HUGIN crane method: four part scales, the hook scale, rope stations and
// the adjustment weight already installed. The sum check and a side view of
// where each scale hangs (and what it reads) follow the typing.
class CraneWeighingPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit CraneWeighingPage(WizardState& state);
  void initializePage() override;
  // Back keeps what was typed (stored, not validated): nothing is lost going back and forth.
  void cleanupPage() override;
  bool validatePage() override;
  bool isComplete() const override;
  int nextId() const override;

 private:
  void store();
  void updateSumCheck();
  void updateSideView();
  WizardState& state_;
  std::array<NumberInput*, 4> scales_{};
  std::array<NumberInput*, 4> installed_{};
  NumberInput* total_;
  NumberInput* rope_fore_;
  NumberInput* rope_aft_;
  NumberInput* rope_y_;
  QLabel* sum_check_;
  QLabel* error_;
  CraneSideView* side_view_;
  bool sum_ok_ = false;
};

}  // namespace auv::ui
