#pragma once
#include <QWizardPage>

#include "wizard/wizard_state.h"

class QGridLayout;
class QGroupBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace auv::ui {

class NumberInput;
class WeightMapWidget;

// Shows the core's first-mission report, whichever weighing produced it
// (crane for an AUV, tank for a glider: the report format is the same): the
// balance before, what to change at each point (table and top-down map) and
// the predicted result against the spec bands. Finish saves the session to
// the history in one transaction.
class FirstMissionResultPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit FirstMissionResultPage(WizardState& state);
  void initializePage() override;
  void cleanupPage() override;
  bool validatePage() override;
  int nextId() const override { return -1; }
  // Writes the first mission's work order (work_order.h) as a PDF; returns
  // an empty string on success, else why not (also shown on the page).
  QString exportPdf(const QString& path);

 private:
  void showReport(const FirstMissionReport& r);
  // "What is actually installed now", one field per point, pre-filled with
  // what was there plus the recommended change; saved as the installed state.
  void buildInstalledInputs(const FirstMissionReport& r);
  void storeInstalled();
  void exportWithDialog();
  WizardState& state_;
  QLabel* before_;
  QLabel* predicted_;
  QLabel* messages_;
  QLabel* save_status_;
  QTableWidget* table_;
  WeightMapWidget* map_;
  QGroupBox* installed_box_;
  QGridLayout* installed_grid_;
  std::vector<NumberInput*> installed_;
  QPushButton* export_pdf_;
  QLabel* export_status_;
};

}  // namespace auv::ui
