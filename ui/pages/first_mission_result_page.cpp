#include "pages/first_mission_result_page.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "firstmission/hugin_first_mission.h"
#include "firstmission/slocum_first_mission.h"
#include "history/store.h"
#include "widgets/fit_scroll_area.h"
#include "widgets/inputs.h"
#include "widgets/weight_map_widget.h"
#include "wizard/advice_text.h"
#include "wizard/history_save.h"
#include "wizard/operator_wizard.h"
#include "wizard/point_labels.h"
#include "wizard/work_order.h"

namespace auv::ui {
namespace {

QString piecesText(const PointRecommendation& p, bool grams) {
  QStringList parts;
  for (const auto& pc : p.pieces) {
    if (pc.count == 0) continue;
    parts << QObject::tr("%1 %2 × %3")
                 .arg(pc.count > 0 ? FirstMissionResultPage::tr("add") : FirstMissionResultPage::tr("remove"))
                 .arg(std::abs(pc.count))
                 .arg(massText(pc.size_kg, grams));
  }
  return parts.isEmpty() ? FirstMissionResultPage::tr("no change") : parts.join(", ");
}

QString band(bool ok) { return ok ? QString("✓") : QString("✗"); }

}  // namespace

FirstMissionResultPage::FirstMissionResultPage(WizardState& state) : state_(state) {
  setTitle(tr("Ballast change before the first mission"));
  before_ = new QLabel;
  before_->setObjectName("before");
  before_->setWordWrap(true);
  predicted_ = new QLabel;
  predicted_->setObjectName("predicted");
  predicted_->setWordWrap(true);
  QScrollArea* scroll = makeMessageArea("messages", &messages_);
  scroll->setMinimumHeight(60);
  save_status_ = makeErrorLabel("save_status");
  table_ = new QTableWidget(0, 3);
  table_->setObjectName("changes");
  table_->setHorizontalHeaderLabels({tr("Point"), tr("Change"), tr("Pieces")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(26);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  map_ = new WeightMapWidget;
  installed_box_ = new QGroupBox(tr("Installed now, after the work (what the next mission flies with)"));
  installed_box_->setObjectName("installed_now");
  installed_grid_ = new QGridLayout(installed_box_);
  // The same one-page PDF work order as before any later mission.
  export_pdf_ = new QPushButton(tr("Export work &order (PDF)…"));
  export_pdf_->setObjectName("export_work_order");
  export_pdf_->setAutoDefault(false);  // Enter means Finish, never a page button
  export_status_ = new QLabel;
  export_status_->setObjectName("work_order_status");
  export_status_->setWordWrap(true);
  connect(export_pdf_, &QPushButton::clicked, this, &FirstMissionResultPage::exportWithDialog);
  auto* export_row = new QHBoxLayout;
  export_row->addWidget(export_pdf_);
  export_row->addWidget(export_status_, 1);
  // Everything in a scroll area: with the glider's steps and the installed
  // masses the page is taller than a 1366 x 768 screen leaves for it.
  auto* content = new QWidget;
  content->setObjectName("result_content");
  auto* page_scroll = new FitScrollArea;
  page_scroll->setObjectName("result_scroll");
  page_scroll->setWidget(content);
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  outer->addWidget(page_scroll);
  auto* lay = new QVBoxLayout(content);
  lay->addWidget(before_);
  lay->addWidget(table_);
  // The map and the notes share the height: for a glider the notes carry
  // the battery, rail and disk steps, which must not scroll out of sight.
  lay->addWidget(map_, 3);
  lay->addWidget(predicted_);
  lay->addWidget(scroll, 2);
  lay->addWidget(installed_box_);
  lay->addLayout(export_row);
  lay->addWidget(save_status_);
}

QString FirstMissionResultPage::exportPdf(const QString& path) {
  QString error;
  try {
    auto* wiz = qobject_cast<OperatorWizard*>(wizard());
    error = writeWorkOrderPdf(makeFirstMissionWorkOrder(state_, wiz ? wiz->now() : nowUtc()), path);
  } catch (const InputError& e) {
    error = QString::fromStdString(e.what());
  }
  export_status_->setStyleSheet(error.isEmpty() ? "color: #1b5e20;" : "color: #b00020;");
  export_status_->setText(error.isEmpty() ? tr("Work order written to %1").arg(path) : tr("Not exported: %1").arg(error));
  return error;
}

void FirstMissionResultPage::exportWithDialog() {
  QSettings settings;
  const QString dir = settings.value("paths/last_export_folder").toString();
  const QString base = QString::fromStdString(state_.configuration_id.empty() ? std::string("first_mission") : state_.configuration_id);
  const QString file = QFileDialog::getSaveFileName(this, tr("Export the work order"), dir + "/" + base + "_work_order.pdf",
                                                    tr("PDF files (*.pdf)"));
  if (file.isEmpty()) return;
  settings.setValue("paths/last_export_folder", QFileInfo(file).absolutePath());
  exportPdf(file);
}

void FirstMissionResultPage::initializePage() {
  state_.report.reset();
  state_.last_error.clear();
  save_status_->clear();
  export_status_->clear();
  const bool tank = state_.isGlider();
  setTitle(tank ? tr("Ballast change after the tank weighing") : tr("Ballast change before the first mission"));
  try {
    if (!state_.vehicle) throw InputError("vehicle", "no vehicle chosen", "go back to the vehicle page");
    state_.report = tank ? slocumFirstMission(*state_.vehicle, state_.tank) : craneFirstMission(*state_.vehicle, state_.crane);
    showReport(*state_.report);
    buildInstalledInputs(*state_.report);
  } catch (const InputError& e) {
    state_.last_error = e.what();
    before_->setText(tr("Cannot compute: %1").arg(QString::fromStdString(e.what())));
    before_->setStyleSheet("color: #b00020;");
  }
}

void FirstMissionResultPage::showReport(const FirstMissionReport& r) {
  const bool g = state_.isGlider();
  const Eigen::Vector3d d = r.cg_m - r.cb_m;
  before_->setStyleSheet(QString());
  const QString net = g ? tr("%1 g").arg(fixed(r.net_buoyancy_kg * 1000.0, 1))
                        : tr("%1 kg").arg(fixed(r.net_buoyancy_kg, 2));
  const QString state = std::abs(r.net_buoyancy_kg) < 5e-4 ? tr("neutral")
                        : r.net_buoyancy_kg > 0            ? tr("too light")
                                                           : tr("too heavy");
  before_->setText(tr("Weighed %1 kg; buoyancy %2 kg in %3 kg/m³ water → net buoyancy %4 (%5). "
                      "CG − CB: x %6 mm, y %7 mm; static pitch %8°, roll %9°.")
                       .arg(fixed(r.weight_kg, g ? 3 : 1))
                       .arg(fixed(r.buoyancy_kg, g ? 3 : 1))
                       .arg(fixed(r.density_kgm3, 2))
                       .arg(net)
                       .arg(state)
                       .arg(fixed(units::mToMm(d.x()), 1))
                       .arg(fixed(units::mToMm(d.y()), 1))
                       .arg(fixed(r.pitch_before_deg, 2))
                       .arg(fixed(r.roll_before_deg, 2)));
  table_->setRowCount(static_cast<int>(r.points.size()));
  for (int i = 0; i < static_cast<int>(r.points.size()); ++i) {
    const auto& p = r.points[static_cast<std::size_t>(i)];
    table_->setItem(i, 0, new QTableWidgetItem(QString::fromStdString(p.label)));
    table_->setItem(i, 1, new QTableWidgetItem(massText(p.add_kg, g, true)));
    table_->setItem(i, 2, new QTableWidgetItem(piecesText(p, g)));
  }
  table_->resizeColumnsToContents();
  // Every point visible without scrolling (6 for a glider, 4 for HUGIN).
  table_->setFixedHeight(table_->horizontalHeader()->sizeHint().height() +
                         table_->verticalHeader()->defaultSectionSize() * table_->rowCount() + 2 * table_->frameWidth());
  map_->setModel(makeWeightMapModel(*state_.vehicle, firstMissionInstalledKg(state_, r), r));
  const auto& spec = state_.vehicle->spec;
  const bool nb_ok = r.predicted.net_buoyancy_kg >= spec.net_buoyancy_min_kg - 1e-9 &&
                     r.predicted.net_buoyancy_kg <= spec.net_buoyancy_max_kg + 1e-9;
  predicted_->setText(tr("After the change: net buoyancy %1 %2 (band %3..%4), pitch %5° %6 (±%7), "
                         "roll %8° %9 (±%10).")
                          .arg(g ? tr("%1 g").arg(fixed(r.predicted.net_buoyancy_kg * 1000.0, 1))
                                 : tr("%1 kg").arg(fixed(r.predicted.net_buoyancy_kg, 2)))
                          .arg(band(nb_ok))
                          .arg(fixed(g ? spec.net_buoyancy_min_kg * 1000.0 : spec.net_buoyancy_min_kg, g ? 0 : 1))
                          .arg(g ? tr("%1 g").arg(fixed(spec.net_buoyancy_max_kg * 1000.0, 0))
                                 : tr("%1 kg").arg(fixed(spec.net_buoyancy_max_kg, 1)))
                          .arg(fixed(r.predicted.pitch_deg, 2))
                          .arg(band(std::abs(r.predicted.pitch_deg) <= spec.pitch_tolerance_deg))
                          .arg(fixed(spec.pitch_tolerance_deg, 1))
                          .arg(fixed(r.predicted.roll_deg, 2))
                          .arg(band(std::abs(r.predicted.roll_deg) <= spec.roll_tolerance_deg))
                          .arg(fixed(spec.roll_tolerance_deg, 1)));
  QStringList msgs;
  for (const auto& w : r.warnings) msgs << tr("⚠ %1").arg(adviceText(w));
  for (const auto& n : r.notes) msgs << adviceText(n);
  const QString text = withPointLabels(msgs.join("\n"), *state_.vehicle);
  messages_->setText(text);
}

void FirstMissionResultPage::buildInstalledInputs(const FirstMissionReport& r) {
  for (auto* w : installed_box_->findChildren<QWidget*>(Qt::FindDirectChildrenOnly)) delete w;
  installed_.clear();
  const VehicleProfile& v = *state_.vehicle;
  const bool g = state_.isGlider();
  const std::vector<double> before = firstMissionInstalledKg(state_, r);
  const bool resumed = state_.actually_installed_kg.size() == v.points.size();
  for (std::size_t i = 0; i < v.points.size(); ++i) {
    const auto& p = v.points[i];
    double kg = i < before.size() ? before[i] : 0.0;
    for (const auto& rp : r.points)
      if (rp.name == p.name) kg += rp.add_kg;
    if (resumed) kg = state_.actually_installed_kg[i];
    const double scale = g ? 1000.0 : 1.0;
    auto* in = makeNumber(QString("installed_now_%1").arg(i), 0.0, std::max(p.capacity_kg, 1.0) * scale * 2, g ? 0 : 2,
                          g ? tr("g") : tr("kg"),
                          tr("What is in '%1' now that the work is done (the recommended result is filled in; "
                             "change it if you installed something else).").arg(QString::fromStdString(p.label)));
    in->setValue(std::max(0.0, kg) * scale);
    auto* label = new QLabel(QString::fromStdString(p.label) + ":");
    label->setBuddy(in);
    const int row = static_cast<int>(i / 3), col = static_cast<int>(i % 3) * 2;
    installed_grid_->addWidget(label, row, col);
    installed_grid_->addWidget(in, row, col + 1);
    installed_.push_back(in);
  }
  storeInstalled();
}

void FirstMissionResultPage::storeInstalled() {
  if (installed_.empty()) return;
  const double scale = state_.isGlider() ? 1000.0 : 1.0;
  state_.actually_installed_kg.clear();
  for (auto* in : installed_) state_.actually_installed_kg.push_back(in->value() / scale);
}

void FirstMissionResultPage::cleanupPage() { storeInstalled(); }

bool FirstMissionResultPage::validatePage() {
  storeInstalled();
  // Finish: the session goes into the history as one transaction.
  auto* wiz = qobject_cast<OperatorWizard*>(wizard());
  if (!state_.report) return false;
  HistoryStore* store = wiz ? wiz->history() : nullptr;
  if (!store) return !wiz || wiz->confirmCloseWithoutHistory();
  try {
    saveFirstMissionToHistory(*store, state_, wiz->now());
  } catch (const InputError& e) {
    save_status_->setText(tr("Not saved: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
  wiz->reportSaved(tr("Saved configuration %1: weighing, water, recommendation and installed state.")
                       .arg(QString::fromStdString(state_.configuration_id)));
  return true;
}

}  // namespace auv::ui
