#include "wizard/operator_wizard.h"

#include <QAbstractButton>
#include <QDateTime>
#include <QFile>
#include <QSettings>
#include <QShortcut>

#include "common/input_error.h"
#include "history/store.h"
#include "pages/adjustment_page.h"
#include "pages/crane_weighing_page.h"
#include "pages/deviation_plots_page.h"
#include "pages/first_mission_result_page.h"
#include "pages/log_import_page.h"
#include "pages/model_check_page.h"
#include "pages/pre_mission_page.h"
#include "pages/roll_test_page.h"
#include "pages/start_page.h"
#include "pages/summary_page.h"
#include "pages/tank_weighing_page.h"
#include "pages/vehicle_page.h"
#include "pages/water_page.h"
#include "widgets/help_dialog.h"
#include "wizard/app_paths.h"

namespace auv::ui {

OperatorWizard::OperatorWizard(WizardState state, QWidget* parent)
    : QWizard(parent), state_(std::move(state)), clock_([] { return nowUtc(); }) {
  setObjectName("operator_wizard");
  setWindowTitle(tr("auvballast - ballast wizard"));
  setWizardStyle(QWizard::ClassicStyle);
  setOption(QWizard::NoBackButtonOnStartPage);
  setOption(QWizard::HaveHelpButton);
  // Our own texts so that the buttons follow the application's translation.
  setButtonText(QWizard::BackButton, tr("< &Back"));
  setButtonText(QWizard::NextButton, tr("&Next >"));
  setButtonText(QWizard::FinishButton, tr("&Finish"));
  setButtonText(QWizard::CancelButton, tr("Cancel"));
  setButtonText(QWizard::HelpButton, tr("&Help"));
  for (auto b : {QWizard::BackButton, QWizard::NextButton, QWizard::FinishButton, QWizard::CancelButton,
                 QWizard::HelpButton}) {
    button(b)->setMinimumHeight(32);
  }
  setPage(kStart, new StartPage(state_));
  setPage(kVehicle, new VehiclePage(state_));
  setPage(kCraneWeighing, new CraneWeighingPage(state_));
  setPage(kWater, new WaterPage(state_));
  setPage(kTankWeighing, new TankWeighingPage(state_));
  setPage(kRollTest, new RollTestPage(state_));
  setPage(kFirstMissionResult, new FirstMissionResultPage(state_));
  setPage(kLogImport, new LogImportPage(state_));
  setPage(kDeviationPlots, new DeviationPlotsPage(state_));
  setPage(kPreMission, new PreMissionPage(state_));
  setPage(kAdjustment, new AdjustmentPage(state_));
  setPage(kSummary, new SummaryPage(state_));
  setPage(kModelCheck, new ModelCheckPage(state_));
  setStartId(kStart);

  connect(this, &QWizard::helpRequested, this, &OperatorWizard::showHelp);
  auto* f1 = new QShortcut(QKeySequence::HelpContents, this);
  connect(f1, &QShortcut::activated, this, &OperatorWizard::showHelp);
  connect(this, &QWizard::currentIdChanged, this, [this](int id) {
    // The start page holds nothing entered yet, and writing there would
    // overwrite the session the start page is offering to resume.
    if (id > kStart) autosave();
  });

  QSettings settings;
  if (!restoreGeometry(settings.value("wizard/geometry").toByteArray())) resize(1000, 760);
}

OperatorWizard::~OperatorWizard() = default;

HistoryStore* OperatorWizard::history() {
  if (!history_tried_) {
    history_tried_ = true;
    try {
      history_ = std::make_unique<HistoryStore>(historyFilePath().toStdString());
    } catch (const InputError& e) {
      history_error_ = QString::fromStdString(e.what());
    }
  }
  return history_.get();
}

void OperatorWizard::autosave() {
  if (!autosave_enabled_) return;
  try {
    writeSessionFile(autosaveFilePath().toStdString(),
                     sessionToJson(state_, currentId(), toIsoUtc(now())));
  } catch (const InputError&) {
    // An autosave that fails must not interrupt the technician; the next
    // page change tries again.
  }
}

void OperatorWizard::discardAutosave() { QFile::remove(autosaveFilePath()); }

bool OperatorWizard::resume(const SavedSession& saved) {
  state_ = saved.state;
  restart();
  while (currentId() != saved.page_id) {
    const int before = currentId();
    if (nextId() == -1) break;
    next();
    if (currentId() == before) return false;  // a page refused its (saved) input
  }
  return currentId() == saved.page_id;
}

void OperatorWizard::showHelp() {
  if (!help_) help_ = new HelpDialog(userGuidePath(), this);
  help_->show();
  help_->raise();
}

void OperatorWizard::done(int result) {
  QSettings().setValue("wizard/geometry", saveGeometry());
  if (result == QDialog::Accepted) discardAutosave();
  QWizard::done(result);
}

}  // namespace auv::ui
