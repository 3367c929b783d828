#pragma once
#include <QWizard>
#include <functional>
#include <memory>

#include "history/timestamp.h"
#include "wizard/session_json.h"
#include "wizard/wizard_state.h"

namespace auv {
class HistoryStore;
}

namespace auv::ui {

class HelpDialog;

// The guided sequence a technician follows on the dockside:
//   start (history, mode) -> vehicle ->
//     first mission, AUV:    crane weighing -> water -> result
//     first mission, glider: tank weighing -> roll test -> result
//     post mission:          log import -> deviation plots -> model check -> pre mission
//     pre mission:           pre mission (next water, policy) -> adjustment -> summary
// Finish saves the session to the history in one transaction.
class OperatorWizard : public QWizard {
  Q_OBJECT
 public:
  enum PageId {
    kStart = 0,
    kVehicle,
    kCraneWeighing,
    kWater,
    kTankWeighing,
    kRollTest,
    kFirstMissionResult,
    kLogImport,
    kDeviationPlots,
    kModelCheck,
    kPreMission,
    kAdjustment,
    kSummary
  };

  explicit OperatorWizard(WizardState state, QWidget* parent = nullptr);
  ~OperatorWizard() override;
  WizardState& state() { return state_; }

  // The history at historyFilePath(), opened on first use; nullptr (and
  // historyError() says why) when it cannot be opened.
  HistoryStore* history();
  QString historyError() const { return history_error_; }

  // "Now" for dates on screen and records; tests fix it so screenshots are stable.
  void setClock(std::function<TimePoint()> clock) { clock_ = std::move(clock); }
  TimePoint now() const { return clock_(); }

  // Autosave of the unfinished session on every page change (off for demos).
  void setAutosaveEnabled(bool on) { autosave_enabled_ = on; }
  void autosave();
  void discardAutosave();
  // Replaces the session with a saved one and walks forward to its page
  // (each page re-reads the state). Returns false if a page refused.
  bool resume(const SavedSession& saved);

  void showHelp();
  HelpDialog* helpDialog() const { return help_; }

  void done(int result) override;

 private:
  WizardState state_;
  std::unique_ptr<HistoryStore> history_;
  QString history_error_;
  bool history_tried_ = false;
  std::function<TimePoint()> clock_;
  bool autosave_enabled_ = true;
  HelpDialog* help_ = nullptr;
};

}  // namespace auv::ui
