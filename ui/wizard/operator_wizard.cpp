#include "wizard/operator_wizard.h"

#include <QAbstractButton>
#include <QApplication>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QDateTime>
#include <QFile>
#include <QSettings>
#include <QShortcut>

#include "common/input_error.h"
#include "history/default_location.h"
#include "history/store.h"
#include "pages/adjustment_page.h"
#include "pages/crane_weighing_page.h"
#include "pages/deviation_plots_page.h"
#include "pages/first_mission_result_page.h"
#include "pages/glider_ballast_page.h"
#include "pages/glider_pre_mission_page.h"
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
#include "widgets/number_input.h"
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
  // Enter is Next/Finish (the default button) even when Back, Cancel or Help
  // has the focus: a focused auto-default button would take Enter instead.
  for (auto b : {QWizard::BackButton, QWizard::CancelButton, QWizard::HelpButton}) {
    if (auto* pb = qobject_cast<QPushButton*>(button(b))) pb->setAutoDefault(false);
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
  setPage(kGliderPreMission, new GliderPreMissionPage(state_));
  setPage(kGliderBallast, new GliderBallastPage(state_));
  setStartId(kStart);

  connect(this, &QWizard::helpRequested, this, &OperatorWizard::showHelp);
  auto* f1 = new QShortcut(QKeySequence::HelpContents, this);
  connect(f1, &QShortcut::activated, this, &OperatorWizard::showHelp);
  connect(this, &QWizard::currentIdChanged, this, [this](int id) {
    // The start page holds nothing entered yet, and writing there would
    // overwrite the session the start page is offering to resume.
    if (id > kStart) autosave();
  });

  autosave_timer_.setSingleShot(true);
  autosave_timer_.setInterval(autosaveDelayMs);
  connect(&autosave_timer_, &QTimer::timeout, this, [this] {
    if (currentId() <= kStart) return;
    // The page's store-without-validating (what Back does), so the autosave
    // holds the fields as they are now, including a value being typed.
    if (QWizardPage* p = currentPage()) p->cleanupPage();
    autosave();
  });
  qApp->installEventFilter(this);

  QSettings settings;
  if (!restoreGeometry(settings.value("wizard/geometry").toByteArray())) resize(1000, 760);
}

OperatorWizard::~OperatorWizard() { qApp->removeEventFilter(this); }

HistoryStore* OperatorWizard::history() {
  if (!history_tried_) {
    history_tried_ = true;
    try {
      const std::string path = historyFilePath().isEmpty() ? defaultHistoryPath() : historyFilePath().toStdString();
      ensureHistoryFolder(path);  // the first launch for this user: the folder does not exist yet
      history_ = std::make_unique<HistoryStore>(path);
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

namespace {
OperatorWizard::Asker& defaultAsker() {
  static OperatorWizard::Asker a;
  return a;
}
}  // namespace

void OperatorWizard::setDefaultAsker(Asker a) { defaultAsker() = std::move(a); }

bool OperatorWizard::ask(const QString& title, const QString& text, bool question) {
  if (asker_) return asker_(title, text, question);
  if (defaultAsker()) return defaultAsker()(title, text, question);
  if (!question) {
    QMessageBox::information(this, title, text);
    return true;
  }
  QMessageBox box(QMessageBox::Question, title, text, QMessageBox::NoButton, this);
  QPushButton* yes = box.addButton(tr("&Close without saving"), QMessageBox::DestructiveRole);
  QPushButton* no = box.addButton(tr("&Stay"), QMessageBox::RejectRole);
  box.setDefaultButton(no);
  box.setEscapeButton(no);
  box.exec();
  return box.clickedButton() == yes;
}

bool OperatorWizard::confirmCloseWithoutHistory() {
  return ask(tr("Nothing will be saved"),
             tr("The history cannot be opened (%1), so this session cannot be saved. Your input stays in "
                "the unfinished session and is offered for resuming at the next start. Close anyway?")
                 .arg(history_error_.isEmpty() ? historyFilePath() : history_error_),
             true);
}

void OperatorWizard::reject() {
  if (hasUnsavedInput()) {
    if (currentPage()) currentPage()->cleanupPage();
    autosave();
    const bool close = ask(tr("Close without saving?"),
                           tr("What you entered in this session is not in the history yet. It stays in the "
                              "unfinished session, which the start page offers to resume. Close anyway?"),
                           true);
    if (!close) return;
  }
  QWizard::reject();
}

bool OperatorWizard::validateCurrentPage() {
  // Every number field of the page is read now (a value still being typed
  // counts); one that is not a number in range stops Next with its name.
  if (QWizardPage* p = currentPage()) {
    for (NumberInput* in : p->findChildren<NumberInput*>()) {
      if (!in->isVisibleTo(p) || !in->isEnabled() || in->commit()) continue;
      QString name = in->accessibleName();
      for (QLabel* l : p->findChildren<QLabel*>())
        if (l->buddy() == in || l->buddy() == in->lineEdit())
          name = l->text().remove('&').remove(QRegularExpression(":$"));
      const QString text = tr("%1: %2").arg(name, in->problem());
      if (auto* err = p->findChild<QLabel*>("error")) {
        err->setText(text);
      } else {
        in->lineEdit()->setToolTip(text);
      }
      in->setFocus(Qt::OtherFocusReason);
      return false;
    }
  }
  return QWizard::validateCurrentPage();
}

void OperatorWizard::initializePage(int id) {
  QWizard::initializePage(id);
  // Enter is Next/Finish from anywhere on the page: a page button (Browse,
  // Export, Undo) with the focus would otherwise take Enter for itself
  // (Space still presses it).
  for (QPushButton* b : page(id)->findChildren<QPushButton*>())
    if (b->window() == this) b->setAutoDefault(false);
  // Tab from the page's last field lands on Next (or Finish), so Enter after
  // Tab goes forward; Back, Cancel and Help follow.
  // Fields a page builds in initializePage join the chain at its end, after
  // the buttons: the buttons go behind the window's last other widget.
  const QList<QWidget*> buttons = {button(QWizard::NextButton), button(QWizard::FinishButton),
                                   button(QWizard::CancelButton), button(QWizard::BackButton),
                                   button(QWizard::HelpButton)};
  QWidget* last = nullptr;
  for (QWidget* w = nextInFocusChain(); w && w != this; w = w->nextInFocusChain())
    if (!buttons.contains(w) && isAncestorOf(w) && !buttons.contains(w->parentWidget())) last = w;
  QWidget* chain[] = {last, button(QWizard::NextButton), button(QWizard::FinishButton), button(QWizard::CancelButton),
                      button(QWizard::BackButton), button(QWizard::HelpButton)};
  for (std::size_t i = 1; i < std::size(chain); ++i)
    if (chain[i - 1]) setTabOrder(chain[i - 1], chain[i]);
}

bool OperatorWizard::eventFilter(QObject* watched, QEvent* event) {
  const auto t = event->type();
  if ((t == QEvent::KeyRelease || t == QEvent::MouseButtonRelease) && autosave_enabled_ && currentId() > kStart) {
    if (auto* w = qobject_cast<QWidget*>(watched); w && isAncestorOf(w)) autosave_timer_.start();
  }
  return QWizard::eventFilter(watched, event);
}

void OperatorWizard::done(int result) {
  QSettings().setValue("wizard/geometry", saveGeometry());
  autosave_timer_.stop();
  // QWizard::done validates (and so saves) the last page first; the wizard
  // closes only if that worked.
  QWizard::done(result);
  if (result == QDialog::Accepted && !isVisible()) {
    discardAutosave();
    if (!saved_text_.isEmpty()) ask(tr("Saved"), saved_text_, false);
  }
}

}  // namespace auv::ui
