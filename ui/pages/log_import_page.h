#pragma once
#include <QPointer>
#include <QWizardPage>
#include <optional>
#include <vector>

#include "missionlog/column_mapping.h"
#include "wizard/log_import_job.h"
#include "wizard/wizard_state.h"

class QGridLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;

namespace auv::ui {

class NumberInput;

class ColumnMappingDialog;

// Post mission, step 1: choose the mission log (file dialog or drag and
// drop; several files of one mission or a folder of them are read as one
// mission, see missionlog/mission_files.h), let the registry recognise its format and read it in a worker
// thread with a progress bar and Cancel, then say what was read and what was
// skipped and why (ReadReport). A vendor text log whose columns the reader
// cannot map opens the column-mapping dialog (also "Map columns…"); a mapping
// saved for the vehicle is used for its text logs without asking. The
// technician also enters the adjustment weight that was installed during
// the mission, which the analysis on the next page needs (AUVs).
class LogImportPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit LogImportPage(WizardState& state);
  void initializePage() override;
  bool isComplete() const override;
  bool validatePage() override;  // also when driven programmatically (resume)
  int nextId() const override;

  // Without a mapping, the one saved for the vehicle (if any) is used.
  void startImport(const QString& path, std::optional<ColumnMapping> mapping = std::nullopt);
  LogImportJob& job() { return job_; }
  // Opens the column-mapping dialog for the file named in the path field
  // (window-modal, returns at once); accepting it re-imports with the mapping.
  void openMappingDialog();
  ColumnMappingDialog* mappingDialog() const;
  // Installed adjustment mass per profile point, as entered (kg).
  std::vector<double> installedKg() const;

 protected:
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;

 private:
  void browse();
  void onFinished(const LogImportOutcome& out);
  void showSummary();
  void buildInstalledInputs();
  void mappingAccepted();
  WizardState& state_;
  LogImportJob job_;
  QLineEdit* path_;
  QPushButton* browse_;
  QPushButton* import_;
  QPushButton* map_;
  QPointer<ColumnMappingDialog> mapping_dialog_;
  QGroupBox* installed_box_;
  QWidget* alignment_row_;   // AUVs: the pitch sensor's level check
  NumberInput* alignment_;
  QLabel* error_;
  QGridLayout* installed_grid_;
  std::vector<NumberInput*> installed_;
  void prefillInstalledFromLog();
  std::string installed_vehicle_;  // profile the spin boxes were built for
  QProgressBar* progress_;
  QPushButton* cancel_;
  QLabel* drop_hint_;
  QLabel* status_;
  QLabel* summary_;
  QListWidget* problems_;
};

}  // namespace auv::ui
