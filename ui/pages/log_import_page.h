#pragma once
#include <QWizardPage>

#include "wizard/log_import_job.h"
#include "wizard/wizard_state.h"

class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;

namespace auv::ui {

// Post mission, step 1: choose the mission log (file dialog or drag and
// drop), let the registry recognise its format and read it in a worker
// thread with a progress bar and Cancel, then say what was read and what was
// skipped and why (ReadReport).
class LogImportPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit LogImportPage(WizardState& state);
  void initializePage() override;
  bool isComplete() const override;
  bool validatePage() override;  // also when driven programmatically (resume)
  int nextId() const override;

  void startImport(const QString& path);
  LogImportJob& job() { return job_; }

 protected:
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;

 private:
  void browse();
  void onFinished(const LogImportOutcome& out);
  void showSummary();
  WizardState& state_;
  LogImportJob job_;
  QLineEdit* path_;
  QPushButton* browse_;
  QPushButton* import_;
  QProgressBar* progress_;
  QPushButton* cancel_;
  QLabel* drop_hint_;
  QLabel* status_;
  QLabel* summary_;
  QListWidget* problems_;
};

}  // namespace auv::ui
