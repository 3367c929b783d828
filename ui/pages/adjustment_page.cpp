#include "pages/adjustment_page.h"

#include "wizard/advice_text.h"

#include <QAction>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QScrollArea>
#include <QTableWidget>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>
#include <cmath>
#include <vector>

#include "common/input_error.h"
#include "firstmission/hugin_first_mission.h"
#include "planning/installed_prediction.h"
#include "widgets/calibration_table.h"
#include "widgets/estimate_text.h"
#include "widgets/inputs.h"
#include "widgets/weight_map_widget.h"
#include "wizard/operator_wizard.h"
#include "wizard/pre_mission_inputs.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

QString mark(bool ok) { return ok ? QStringLiteral("✓") : QStringLiteral("✗"); }
QColor passColour(bool ok) { return ok ? QColor(200, 230, 201) : QColor(255, 205, 210); }

}  // namespace

// One edit of one point's actually installed mass.
class SetInstalledCommand : public QUndoCommand {
 public:
  SetInstalledCommand(AdjustmentPage* page, std::size_t point, double before, double after)
      : page_(page), point_(point), before_(before), after_(after) {
    setText(AdjustmentPage::tr("installed mass"));
  }
  void redo() override { page_->applyInstalled(point_, after_); }
  void undo() override { page_->applyInstalled(point_, before_); }

 private:
  AdjustmentPage* page_;
  std::size_t point_;
  double before_, after_;
};

AdjustmentPage::AdjustmentPage(WizardState& state) : state_(state) {
  setTitle(tr("Adjust the ballast"));
  setSubTitle(tr("Do the steps, tick each one, then enter what is actually in each point if it differs."));

  map_ = new WeightMapWidget;
  map_->setMinimumHeight(160);

  prediction_ = new QTableWidget(4, 5);
  prediction_->setObjectName("prediction");
  prediction_->setHorizontalHeaderLabels({tr("Quantity"), tr("Now"), tr("After (± 1σ)"), tr("Band"), QString()});
  prediction_->verticalHeader()->hide();
  prediction_->verticalHeader()->setDefaultSectionSize(24);
  prediction_->horizontalHeader()->setStretchLastSection(true);
  prediction_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  prediction_->setFocusPolicy(Qt::NoFocus);
  prediction_->setSelectionMode(QAbstractItemView::NoSelection);
  // Four short rows: never a scroll bar that would hide the last one.
  prediction_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  prediction_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  prediction_->setToolTip(tr("What the vehicle will do at the operating depth, against the spec bands. "
                             "Green: inside the band, red: outside."));
  prediction_->setFixedHeight(prediction_->horizontalHeader()->sizeHint().height() + 4 * 24 + 2 * prediction_->frameWidth());

  QScrollArea* scroll = makeMessageArea("messages", &messages_);
  // What the analysis calibrated and, when asked for, the manoeuvre that
  // would identify the rest (issue 11).
  calibration_ = new CalibrationTable;
  calibration_->setMaximumHeight(130);
  manoeuvre_ = new QLabel;
  manoeuvre_->setObjectName("calibration_manoeuvre");
  manoeuvre_->setWordWrap(true);
  manoeuvre_->setTextFormat(Qt::RichText);

  auto* stepsLabel = new QLabel(tr("&Steps (tick each when done):"));
  checklist_ = new QListWidget;
  checklist_->setObjectName("checklist");
  checklist_->setToolTip(tr("Do the steps in this order: removals first. Space ticks the selected step."));
  stepsLabel->setBuddy(checklist_);
  progress_ = new QLabel;
  progress_->setObjectName("checklist_progress");

  auto* instBox = new QGroupBox(tr("Actually installed"));
  auto* grid = installed_grid_ = new QGridLayout;
  actual_prediction_ = new QLabel;
  actual_prediction_->setObjectName("actual_prediction");
  actual_prediction_->setWordWrap(true);
  actual_prediction_->setMinimumHeight(3 * actual_prediction_->fontMetrics().lineSpacing() + 4);
  undo_ = new QUndoStack(this);
  // Own actions (not createUndoAction) so that the buttons keep a short, fixed text.
  undo_action_ = new QAction(tr("&Undo"), this);
  undo_action_->setShortcut(QKeySequence::Undo);
  undo_action_->setEnabled(false);
  connect(undo_action_, &QAction::triggered, undo_, &QUndoStack::undo);
  connect(undo_, &QUndoStack::canUndoChanged, undo_action_, &QAction::setEnabled);
  redo_action_ = new QAction(tr("&Redo"), this);
  redo_action_->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence::Redo});
  redo_action_->setEnabled(false);
  connect(redo_action_, &QAction::triggered, undo_, &QUndoStack::redo);
  connect(undo_, &QUndoStack::canRedoChanged, redo_action_, &QAction::setEnabled);
  for (QAction* a : {undo_action_, redo_action_}) {
    a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(a);
  }
  auto* undoButton = new QToolButton;
  undoButton->setObjectName("undo");
  undoButton->setDefaultAction(undo_action_);
  undoButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
  undoButton->setToolTip(tr("Undo the last change of an installed mass (Ctrl+Z)."));
  auto* redoButton = new QToolButton;
  redoButton->setObjectName("redo");
  redoButton->setDefaultAction(redo_action_);
  redoButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
  redoButton->setToolTip(tr("Redo the change undone last (Ctrl+Shift+Z)."));
  auto* undoRow = new QHBoxLayout;
  undoRow->addWidget(undoButton);
  undoRow->addWidget(redoButton);
  undoRow->addStretch();
  error_ = makeErrorLabel("actual_error");
  auto* il = new QVBoxLayout(instBox);
  il->addLayout(grid);
  il->addLayout(undoRow);
  il->addWidget(actual_prediction_);
  il->addWidget(error_);

  auto* left = new QVBoxLayout;
  left->addWidget(prediction_);
  left->addWidget(manoeuvre_);
  left->addWidget(scroll, 1);
  auto* right = new QVBoxLayout;
  auto* stepsHead = new QHBoxLayout;
  stepsHead->addWidget(stepsLabel);
  stepsHead->addStretch();
  stepsHead->addWidget(progress_);
  right->addLayout(stepsHead);
  right->addWidget(checklist_, 1);
  right->addWidget(calibration_);
  right->addWidget(instBox);
  auto* lower = new QHBoxLayout;
  lower->addLayout(left, 5);
  lower->addLayout(right, 4);
  auto* lay = new QVBoxLayout(this);
  lay->addWidget(map_, 1);
  lay->addLayout(lower, 2);

  connect(checklist_, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
    const int row = checklist_->row(item);
    if (row < 0) return;
    if (state_.checklist_done.size() < static_cast<std::size_t>(checklist_->count()))
      state_.checklist_done.resize(static_cast<std::size_t>(checklist_->count()), false);
    state_.checklist_done[static_cast<std::size_t>(row)] = item->checkState() == Qt::Checked;
    QFont f = item->font();
    f.setStrikeOut(item->checkState() == Qt::Checked);
    item->setFont(f);
    updateProgress();
  });
}

std::vector<double> AdjustmentPage::planned() const {
  return state_.plan ? installedAfterPlan(before_, *state_.plan) : std::vector<double>{};
}

void AdjustmentPage::initializePage() {
  error_->clear();
  undo_->clear();
  before_ = installedNow(state_);
  if (!state_.plan || !state_.vehicle) return;
  const VehicleProfile& v = *state_.vehicle;
  const PreMissionPlan& plan = *state_.plan;
  const std::vector<double> plan_after = planned();
  if (state_.actually_installed_kg.size() != plan_after.size()) state_.actually_installed_kg = plan_after;

  // The installed editor, one spin box per point (rebuilt for this vehicle).
  QGridLayout* grid = installed_grid_;
  for (auto* s : actual_) delete s;
  for (auto* l : actual_labels_) delete l;
  actual_.clear();
  actual_labels_.clear();
  const bool g = state_.isGlider();
  const int decimals = massDecimals(plan.piece_sizes_kg);
  const double step = plan.piece_sizes_kg.empty() ? 0.1 : plan.piece_sizes_kg.front();
  // Two points a row, or one where the labels are long (Delphin2's "Fore
  // trim weight (assumed position)"): two long labels a row squeezed the
  // quantity table beside them out of its band column.
  qsizetype longest = 0;
  for (const AdjustmentPoint& ap : v.points) longest = std::max(longest, q(ap.label).size());
  const int per_row = longest > 24 ? 1 : 2;
  for (std::size_t i = 0; i < v.points.size(); ++i) {
    const AdjustmentPoint& ap = v.points[i];
    auto* spin = makeNumber(QString("actual_%1").arg(i), 0, ap.capacity_kg > 0 ? ap.capacity_kg : 1000.0, decimals, " kg",
                          tr("Kit pieces now in '%1' after the work, in kg. Planned: %2. Arrows step by one %3 piece; "
                             "Ctrl+Z undoes.")
                              .arg(q(ap.label), massText(plan_after[i], g), massText(step, g)));
    spin->setSingleStep(step);
    spin->setValue(state_.actually_installed_kg[i]);
    spin->lineEdit()->installEventFilter(this);
    auto* label = new QLabel(q(ap.label) + ":");
    label->setBuddy(spin);
    const int row = static_cast<int>(i) / per_row, col = (static_cast<int>(i) % per_row) * 2;
    grid->addWidget(label, row, col);
    grid->addWidget(spin, row, col + 1);
    actual_.push_back(spin);
    actual_labels_.push_back(label);
    connect(spin, &NumberInput::valueChanged, this, [this, i](double kg) {
      if (applying_) return;
      const double old = state_.actually_installed_kg[i];
      undo_->push(new SetInstalledCommand(this, i, old, kg));
    });
  }
  // Tab order: checklist, then the installed masses in profile order.
  QWidget* prev = checklist_;
  for (auto* s : actual_) {
    setTabOrder(prev, s);
    prev = s;
  }

  // The checklist: one line per changed (point, size) pair.
  checklist_->blockSignals(true);
  checklist_->clear();
  const std::vector<ChecklistStep> steps = checklistSteps(plan);
  if (state_.checklist_done.size() != steps.size()) state_.checklist_done.assign(steps.size(), false);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const ChecklistStep& s = steps[k];
    const QString text = (s.count > 0 ? tr("Add %1 × %2 at %3") : tr("Remove %1 × %2 at %3"))
                             .arg(std::abs(s.count))
                             .arg(massText(s.size_kg, g))
                             .arg(q(v.points[s.point].label));
    auto* item = new QListWidgetItem(text, checklist_);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
    item->setCheckState(state_.checklist_done[k] ? Qt::Checked : Qt::Unchecked);
    item->setForeground(s.count > 0 ? QColor(27, 94, 32) : QColor(176, 0, 32));
    QFont f = item->font();
    f.setStrikeOut(state_.checklist_done[k]);
    item->setFont(f);
  }
  if (steps.empty()) {
    auto* item = new QListWidgetItem(tr("Nothing to change: the vehicle stays as it is."), checklist_);
    item->setFlags(Qt::ItemIsEnabled);
  }
  checklist_->blockSignals(false);
  updateProgress();
  showPlan();
  showCalibration();
  showActualPrediction();
}

void AdjustmentPage::showCalibration() {
  // The report the plan started from (this session's estimate or the history's).
  nlohmann::json report;
  try {
    auto* w = qobject_cast<OperatorWizard*>(wizard());
    report = planBasis(state_, w ? w->history() : nullptr, w ? w->now() : nowUtc(), state_.policy).report;
  } catch (const InputError&) {
    // No analysis to plan from: nothing was calibrated.
  }
  calibration_->showRows(CalibrationTable::rowsFromJson(report.value("calibration", nlohmann::json::array())));
  const QStringList legs =
      state_.plan->calibration_manoeuvre ? CalibrationTable::manoeuvreLines(*state_.plan->calibration_manoeuvre) : QStringList();
  const QString after = CalibrationTable::afterMoveLine(state_.plan->after_move_net_sigma_kg, state_.plan->after_move_x_sigma_m);
  manoeuvre_->setVisible(!legs.isEmpty() || !after.isEmpty());
  QStringList text;
  if (!legs.isEmpty())
    text << tr("<b>Calibration manoeuvre</b> to add to the next mission: %1").arg(legs.join(". ").toHtmlEscaped());
  if (!after.isEmpty()) text << after.toHtmlEscaped();
  manoeuvre_->setText(text.join("<br>"));
}

void AdjustmentPage::updateProgress() {
  const std::size_t n = state_.plan ? checklistSteps(*state_.plan).size() : 0;
  std::size_t done = 0;
  for (std::size_t k = 0; k < n && k < state_.checklist_done.size(); ++k) done += state_.checklist_done[k] ? 1 : 0;
  progress_->setText(tr("%1 of %2 done").arg(done).arg(n));
  progress_->setStyleSheet(done == n ? "color: #1b5e20;" : QString());
}

void AdjustmentPage::showPlan() {
  const VehicleProfile& v = *state_.vehicle;
  const PreMissionPlan& p = *state_.plan;
  const bool g = state_.isGlider();
  map_->setModel(makeWeightMapModel(v, before_, p.points));

  const TrimSpec& spec = v.spec;
  const int nd = g ? 3 : 2;
  struct Row {
    QString name, now, after, band;
    std::optional<bool> ok;  // unset: not known
  };
  const bool pitch_known = EstimateText::pitchKnown(p), roll_known = EstimateText::rollKnown(p);
  std::vector<Row> rows = {
      {tr("Net buoyancy"), tr("%1 kg").arg(signedFixed(p.net_before_kg, nd)),
       tr("%1 ± %2 kg").arg(signedFixed(p.predicted.net_buoyancy_kg, nd), fixed(p.net_sigma_kg, nd)),
       tr("%1 .. %2 kg").arg(fixed(std::max(0.0, spec.net_buoyancy_min_kg), 1), fixed(spec.net_buoyancy_max_kg, 1)),
       p.buoyancy_in_band},
      {tr("Pitch at rest"), pitch_known ? tr("%1°").arg(signedFixed(p.pitch_before_deg, 2)) : EstimateText::notKnown(),
       EstimateText::valueSigma(pitch_known, p.predicted.pitch_deg, p.pitch_sigma_deg, 2, tr("°")),
       tr("±%1°").arg(fixed(spec.pitch_tolerance_deg, 1)), pitch_known ? std::optional<bool>(p.pitch_in_band) : std::nullopt},
      {tr("Roll"), roll_known ? tr("%1°").arg(signedFixed(p.roll_before_deg, 2)) : EstimateText::notKnown(),
       EstimateText::valueSigma(roll_known, p.predicted.roll_deg, p.roll_sigma_deg, 2, tr("°")),
       tr("±%1°").arg(fixed(spec.roll_tolerance_deg, 1)), roll_known ? std::optional<bool>(p.roll_in_band) : std::nullopt}};
  // The spec's pitch band is about the pitch flown level (thesis §5.3.2);
  // shown when the profile's hydrodynamics and the cruise speed allow it.
  if (p.flight_pitch_after_deg && p.flight_pitch_before_deg) {
    rows.insert(rows.begin() + 2,
                Row{tr("Pitch in flight (%1 m/s)").arg(fixed(p.flight_speed_mps, 1)),
                    tr("%1°").arg(signedFixed(*p.flight_pitch_before_deg, 2)),
                    tr("%1°").arg(signedFixed(*p.flight_pitch_after_deg, 2)),
                    tr("±%1°").arg(fixed(spec.pitch_tolerance_deg, 1)), p.flight_pitch_in_band.value_or(false)});
  }
  prediction_->setRowCount(static_cast<int>(rows.size()));
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const Row& row = rows[static_cast<std::size_t>(r)];
    const QString cells[5] = {row.name, row.now, row.after, row.band, row.ok ? mark(*row.ok) : QStringLiteral("?")};
    for (int c = 0; c < 5; ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      if (c >= 2 && row.ok) item->setBackground(passColour(*row.ok));
      if (c == 4) item->setTextAlignment(Qt::AlignCenter);
      prediction_->setItem(r, c, item);
    }
  }
  prediction_->resizeColumnsToContents();

  QStringList lines;
  for (const auto& w : p.warnings) lines << QString("<span style='color:#b00020'>⚠ %1</span>").arg(adviceText(w).toHtmlEscaped());
  for (const auto& e : p.explanations) lines << adviceText(e).toHtmlEscaped();
  QStringList pts;
  for (const auto& r : p.at_points) {
    pts << tr("%1 m %2 kg").arg(fixed(r.water.depth_m, 0)).arg(signedFixed(r.net_after_kg, nd));
  }
  lines << (p.safe ? tr("Safety: net buoyancy stays above the margin %1 kg (%2) at every planned depth: %3.")
                   : tr("<span style='color:#b00020'>Not safe: net buoyancy falls below the margin %1 kg (%2) at a "
                        "planned depth: %3.</span>"))
               .arg(fixed(p.margin_kg, nd), tr("1.645 σ"), pts.join(", "));
  messages_->setText(lines.join("<br>"));
}

void AdjustmentPage::showActualPrediction() {
  if (!state_.plan || !state_.vehicle) return;
  const PreMissionPlan& p = *state_.plan;
  const std::vector<double> plan_after = planned();
  QStringList differ;
  for (std::size_t i = 0; i < plan_after.size() && i < state_.actually_installed_kg.size(); ++i) {
    const bool d = std::abs(state_.actually_installed_kg[i] - plan_after[i]) > 5e-5;
    if (d) differ << q(state_.vehicle->points[i].label);
    if (i < actual_.size()) actual_[i]->setStyleSheet(d ? "background: #fff4cc;" : QString());
  }
  if (differ.isEmpty()) {
    actual_prediction_->setStyleSheet(QString());
    actual_prediction_->setText(tr("As planned: the prediction above holds."));
    return;
  }
  try {
    const InstalledPrediction r = predictInstalled(*state_.vehicle, p, before_, state_.actually_installed_kg);
    const bool g = state_.isGlider();
    const int nd = g ? 3 : 2;
    const bool pitch_known = EstimateText::pitchKnown(p), roll_known = EstimateText::rollKnown(p);
    const bool all = r.buoyancy_in_band && (r.pitch_in_band || !pitch_known) && (r.roll_in_band || !roll_known) && r.safe;
    actual_prediction_->setStyleSheet(all ? "color: #1b5e20;" : "color: #b00020;");
    actual_prediction_->setText(
        tr("Differs from the plan at %1. As installed: net buoyancy %2 %3, pitch %4 %5, roll %6 %7%8")
            .arg(differ.join(", "))
            .arg(EstimateText::valueSigma(true, r.net_buoyancy_kg, r.net_sigma_kg, nd, tr(" kg")), mark(r.buoyancy_in_band))
            .arg(EstimateText::valueSigma(pitch_known, r.pitch_deg, r.pitch_sigma_deg, 2, tr("°")),
                 pitch_known ? mark(r.pitch_in_band) : QString())
            .arg(EstimateText::valueSigma(roll_known, r.roll_deg, r.roll_sigma_deg, 2, tr("°")),
                 roll_known ? mark(r.roll_in_band) : QString())
            .arg(r.safe ? tr(".") : tr("; NOT safe at every planned depth.")) +
        (r.flight_pitch_deg ? tr(" Pitch in flight %1° %2.").arg(signedFixed(*r.flight_pitch_deg, 2),
                                                                   mark(r.flight_pitch_in_band.value_or(false)))
                            : QString()));
    error_->clear();
  } catch (const InputError& e) {
    actual_prediction_->clear();
    error_->setText(q(e.what()));
  }
}

void AdjustmentPage::applyInstalled(std::size_t point, double kg) {
  if (point >= state_.actually_installed_kg.size()) return;
  state_.actually_installed_kg[point] = kg;
  if (point < actual_.size() && actual_[point]->value() != kg) {
    applying_ = true;
    actual_[point]->setValue(kg);
    applying_ = false;
  }
  showActualPrediction();
}

void AdjustmentPage::editInstalled(std::size_t point, double kg) {
  if (point < actual_.size()) actual_[point]->setValue(kg);
}

bool AdjustmentPage::eventFilter(QObject* watched, QEvent* event) {
  // A spin box's line edit claims Ctrl+Z for its own text undo; here the
  // page's undo of whole values wins, so the shortcut works from any field.
  if (event->type() == QEvent::ShortcutOverride) {
    auto* k = static_cast<QKeyEvent*>(event);
    if (k->matches(QKeySequence::Undo) || k->matches(QKeySequence::Redo) ||
        k->keyCombination() == QKeyCombination(Qt::CTRL | Qt::SHIFT, Qt::Key_Z)) {
      event->ignore();
      return true;
    }
  }
  return QWizardPage::eventFilter(watched, event);
}

void AdjustmentPage::cleanupPage() {
  // Back keeps the ticks and masses: the pre-mission page resets them only
  // when the plan changes.
}

bool AdjustmentPage::validatePage() {
  if (!state_.plan || !state_.vehicle) return false;
  // Only whole kit pieces can be in a point.
  for (std::size_t i = 0; i < state_.actually_installed_kg.size(); ++i) {
    try {
      decomposeInstalled(state_.actually_installed_kg[i], state_.plan->piece_sizes_kg, state_.vehicle->points[i].name);
    } catch (const InputError& e) {
      error_->setText(tr("%1: %2").arg(q(state_.vehicle->points[i].label), q(e.what())));
      if (i < actual_.size()) actual_[i]->setFocus();
      return false;
    }
  }
  try {
    predictInstalled(*state_.vehicle, *state_.plan, before_, state_.actually_installed_kg);
  } catch (const InputError& e) {
    error_->setText(q(e.what()));
    return false;
  }
  return true;
}

int AdjustmentPage::nextId() const { return OperatorWizard::kSummary; }

}  // namespace auv::ui
