#pragma once
#include <QWizardPage>
#include <optional>

#include "wizard/pre_mission_inputs.h"
#include "wizard/wizard_state.h"

class QLabel;
class QPushButton;

namespace auv::ui {

class OperatorWizard;

// Pre mission, last step: what Finish saves to the history (in one
// transaction: the imported mission if any, the next mission's water, the
// plan as the accepted recommendation and what was actually installed), a
// preview of the one-page work order, and exports of that work order (PDF)
// and of the JSON report.
class SummaryPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit SummaryPage(WizardState& state);
  void initializePage() override;
  bool validatePage() override;
  int nextId() const override { return -1; }

  // Exports without a dialog (the buttons ask for the path, tests pass it).
  // Return an empty string on success, else why not (also shown on the page).
  QString exportPdf(const QString& path);
  QString exportJson(const QString& path);

 private:
  OperatorWizard* wiz() const;
  void showSummary();
  void exportWithDialog(bool pdf);
  WizardState& state_;
  std::optional<PlanBasis> basis_;
  QLabel* summary_;
  QLabel* preview_;
  QPushButton* export_pdf_;
  QPushButton* export_json_;
  QLabel* export_status_;
  QLabel* save_status_;
};

}  // namespace auv::ui
