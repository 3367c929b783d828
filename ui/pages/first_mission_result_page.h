#pragma once
#include <QWizardPage>

#include "wizard/wizard_state.h"

class QLabel;
class QTableWidget;

namespace auv::ui {

class WeightMapWidget;

// Shows the core's first-mission report: the balance before, what to change
// at each point (table and top-down map) and the predicted result against
// the spec bands.
class FirstMissionResultPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit FirstMissionResultPage(WizardState& state);
  void initializePage() override;
  int nextId() const override { return -1; }

 private:
  void showReport(const FirstMissionReport& r);
  WizardState& state_;
  QLabel* before_;
  QLabel* predicted_;
  QLabel* messages_;
  QTableWidget* table_;
  WeightMapWidget* map_;
};

}  // namespace auv::ui
