#pragma once
#include <QWizardPage>
#include <optional>
#include <vector>

#include "history/records.h"
#include "wizard/wizard_state.h"

class QLabel;
class QLineEdit;
class QTableWidget;
class QRadioButton;
class QFrame;
class QPushButton;

namespace auv::ui {

class OperatorWizard;

// Where a session starts: pick a configuration from the history (recent
// ones, or search) or start a new one, see its last state - installed
// pieces, last mission, and whether the water temperature is older than one
// month (thesis §5.5.3) - and choose the mode. Offers to resume an
// unfinished session found on disk.
class StartPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit StartPage(WizardState& state);
  void initializePage() override;
  bool validatePage() override;
  int nextId() const override;

  // The configuration selected in the table, or nullopt for "new".
  std::optional<Configuration> selectedConfiguration() const;

 private:
  OperatorWizard* wiz() const;
  void refreshTable();
  void showSelection();
  void showResumeOffer();
  void applyConfiguration(const Configuration& c);
  WizardState& state_;
  std::vector<Configuration> rows_;  // table row i+1 (row 0 = new configuration)
  QFrame* resume_box_;
  QLabel* resume_text_;
  QPushButton* resume_;
  QPushButton* discard_;
  QLineEdit* search_;
  QLabel* history_location_;
  QTableWidget* table_;
  QLabel* last_state_;
  QLabel* temperature_;
  QRadioButton* mode_first_;
  QRadioButton* mode_post_;
  QRadioButton* mode_pre_;
  QLabel* error_;
};

}  // namespace auv::ui
