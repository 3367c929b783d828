#pragma once
#include <QTimer>
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
//                            (gliders: -> glider target water -> where the grams go)
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
    kSummary,
    // Gliders after the model check (appended: saved sessions keep their ids).
    kGliderPreMission,
    kGliderBallast
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

  // Autosave of the unfinished session on every page change and, debounced
  // (autosaveDelayMs), after every edit (off for demos).
  void setAutosaveEnabled(bool on) { autosave_enabled_ = on; }
  static constexpr int autosaveDelayMs = 700;
  void autosave();
  void discardAutosave();
  // Replaces the session with a saved one and walks forward to its page
  // (each page re-reads the state). Returns false if a page refused.
  bool resume(const SavedSession& saved);

  void showHelp();
  HelpDialog* helpDialog() const { return help_; }

  // Messages that need the technician: a question (true = the first,
  // affirmative answer) or, with question false, a note to acknowledge.
  // Tests replace the default QMessageBox to read and answer them.
  using Asker = std::function<bool(const QString& title, const QString& text, bool question)>;
  void setAsker(Asker a) { asker_ = std::move(a); }
  // For every wizard without its own asker (the test main answers for the
  // technician and keeps the texts).
  static void setDefaultAsker(Asker a);
  bool ask(const QString& title, const QString& text, bool question);

  // Finish: what the page saved ("configuration 02-01-01: weighing, ..."),
  // confirmed to the technician when the wizard closes.
  void reportSaved(const QString& what) { saved_text_ = what; }
  // The history cannot be opened at Finish: asks whether to close anyway.
  bool confirmCloseWithoutHistory();
  // Anything entered beyond the start page and not yet saved.
  bool hasUnsavedInput() const { return currentId() > kStart && saved_text_.isEmpty(); }

  void done(int result) override;
  void reject() override;
  bool validateCurrentPage() override;

 protected:
  void initializePage(int id) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  WizardState state_;
  std::unique_ptr<HistoryStore> history_;
  QString history_error_;
  bool history_tried_ = false;
  std::function<TimePoint()> clock_;
  bool autosave_enabled_ = true;
  HelpDialog* help_ = nullptr;
  Asker asker_;
  QString saved_text_;
  // Autosave shortly after the last key or click, so a crash loses nothing typed.
  QTimer autosave_timer_;
};

}  // namespace auv::ui
