#pragma once
#include <QWizardPage>
#include <vector>

#include "wizard/wizard_state.h"

class QGridLayout;
class QLabel;
class QListWidget;
class QTableWidget;
class QUndoStack;
class QAction;

namespace auv::ui {

class NumberInput;
class CalibrationTable;

class WeightMapWidget;

// Pre mission, step 2: the plan on the top-down map (installed pieces, green
// to add, red to remove), what the vehicle will do after the move against the
// spec bands with its uncertainty, the plan's explanations and warnings, the
// step-by-step checklist the technician ticks, and what was actually
// installed per point (default: the plan; this is what gets saved). Edits of
// the installed masses can be undone (Ctrl+Z) and redone (Ctrl+Shift+Z); when
// they differ from the plan, core predicts the vehicle with them.
class AdjustmentPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit AdjustmentPage(WizardState& state);
  void initializePage() override;
  void cleanupPage() override;
  bool validatePage() override;
  int nextId() const override;

  QUndoStack* undoStack() const { return undo_; }
  // Sets one point's actually installed mass as an undoable edit (what the spin box does).
  void editInstalled(std::size_t point, double kg);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  friend class SetInstalledCommand;
  void applyInstalled(std::size_t point, double kg);  // no undo entry
  void showPlan();
  void showActualPrediction();
  void showCalibration();  // what was calibrated and the manoeuvre, if asked for
  void updateProgress();
  std::vector<double> planned() const;

  WizardState& state_;
  std::vector<double> before_;  // installed when the plan started
  bool applying_ = false;
  WeightMapWidget* map_;
  QTableWidget* prediction_;
  QLabel* messages_;
  CalibrationTable* calibration_;
  QLabel* manoeuvre_;
  QListWidget* checklist_;
  QLabel* progress_;
  QGridLayout* installed_grid_;
  std::vector<NumberInput*> actual_;
  std::vector<QLabel*> actual_labels_;
  QLabel* actual_prediction_;
  QLabel* error_;
  QUndoStack* undo_;
  QAction* undo_action_;
  QAction* redo_action_;
};

}  // namespace auv::ui
