#include "pages/summary_page.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>
#include <cmath>

#include "common/input_error.h"
#include "history/store.h"
#include "widgets/inputs.h"
#include "wizard/history_save.h"
#include "wizard/operator_wizard.h"
#include "wizard/work_order.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

SummaryPage::SummaryPage(WizardState& state) : state_(state) {
  setTitle(tr("Summary and save"));
  setSubTitle(tr("Finish saves all of this to the history in one step. Export the work order for the vehicle's logbook."));
  summary_ = new QLabel;
  summary_->setObjectName("save_summary");
  summary_->setWordWrap(true);
  summary_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  preview_ = new QLabel;
  preview_->setObjectName("work_order_preview");
  preview_->setFixedSize(300, 424);  // A4 proportions
  preview_->setFrameShape(QFrame::Box);
  preview_->setToolTip(tr("The work order as it will be printed (export it as PDF)."));
  export_pdf_ = new QPushButton(tr("Export work &order (PDF)…"));
  export_pdf_->setObjectName("export_pdf");
  export_pdf_->setToolTip(tr("One A4 page: vehicle, configuration, water, what to change where, the expected result "
                             "and a signature line."));
  export_json_ = new QPushButton(tr("Export &JSON report…"));
  export_json_->setObjectName("export_json");
  export_json_->setToolTip(tr("The plan, the sources and what was actually installed, for other tools."));
  for (auto* b : {export_pdf_, export_json_}) {
    b->setMinimumHeight(32);
    b->setAutoDefault(false);  // Enter means Finish in a wizard, never a page button
  }
  export_status_ = new QLabel;
  export_status_->setObjectName("export_status");
  export_status_->setWordWrap(true);
  save_status_ = makeErrorLabel("save_status");

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(export_pdf_);
  buttons->addWidget(export_json_);
  buttons->addStretch();
  auto* left = new QVBoxLayout;
  left->addWidget(summary_, 1);
  left->addLayout(buttons);
  left->addWidget(export_status_);
  left->addWidget(save_status_);
  auto* lay = new QHBoxLayout(this);
  lay->addLayout(left, 1);
  lay->addWidget(preview_, 0, Qt::AlignTop);

  connect(export_pdf_, &QPushButton::clicked, this, [this] { exportWithDialog(true); });
  connect(export_json_, &QPushButton::clicked, this, [this] { exportWithDialog(false); });
}

OperatorWizard* SummaryPage::wiz() const { return qobject_cast<OperatorWizard*>(wizard()); }

void SummaryPage::initializePage() {
  export_status_->clear();
  save_status_->clear();
  basis_.reset();
  OperatorWizard* w = wiz();
  try {
    basis_ = planBasis(state_, w ? w->history() : nullptr, w ? w->now() : nowUtc(), state_.policy);
  } catch (const InputError& e) {
    save_status_->setText(q(e.what()));
  }
  showSummary();
}

void SummaryPage::showSummary() {
  if (!basis_ || !state_.plan || !state_.vehicle) {
    summary_->clear();
    preview_->clear();
    return;
  }
  const VehicleProfile& v = *state_.vehicle;
  const PreMissionPlan& p = *state_.plan;
  const bool g = state_.isGlider();
  OperatorWizard* w = wiz();
  const TimePoint now = w ? w->now() : nowUtc();
  QStringList items;
  if (state_.mode == SessionMode::kPostMission && state_.log) {
    items << tr("the mission log <b>%1</b> with its read summary").arg(QFileInfo(q(state_.log_file)).fileName().toHtmlEscaped());
  }
  const PlannedPointResult& op = p.at_points.front();
  items << tr("the next mission's water: %1 m, %2 °C, %3 PSU (%4)")
               .arg(fixed(op.water.depth_m, 0))
               .arg(fixed(op.water.temperature_degC, 2))
               .arg(fixed(op.water.salinity_psu, 2))
               .arg(state_.next_water_source == "operator" ? tr("entered") : tr("last mission's CTD"));
  items << tr("the plan (%1 policy) as the accepted recommendation, from %2")
               .arg(q(toString(p.policy)), q(basis_->analysis_name).toHtmlEscaped());
  const std::vector<double> planned = installedAfterPlan(basis_->installed_kg, p);
  const std::vector<double>& actual =
      state_.actually_installed_kg.size() == planned.size() ? state_.actually_installed_kg : planned;
  QStringList pts;
  bool differs = false;
  for (std::size_t i = 0; i < v.points.size(); ++i) {
    const bool d = std::abs(actual[i] - planned[i]) > 5e-5;
    differs = differs || d;
    QString t = QString("%1 %2").arg(q(v.points[i].label).toHtmlEscaped(), massText(actual[i], g));
    if (d) t += tr(" <i>(plan %1)</i>").arg(massText(planned[i], g));
    pts << t;
  }
  items << (differs ? tr("what is actually installed, <b>different from the plan</b>: %1")
                    : tr("what is actually installed, as planned: %1"))
               .arg(pts.join(", "));
  const std::size_t steps = checklistSteps(p).size();
  std::size_t done = 0;
  for (std::size_t k = 0; k < steps && k < state_.checklist_done.size(); ++k) done += state_.checklist_done[k] ? 1 : 0;
  QString text = tr("<b>Finish saves to the history</b> of configuration <b>%1</b>, all together or nothing:")
                     .arg(q(state_.configuration_id).toHtmlEscaped());
  text += "<ul>";
  for (const auto& i : items) text += "<li>" + i + "</li>";
  text += "</ul>";
  text += tr("Checklist: %1 of %2 steps ticked.").arg(done).arg(steps);
  if (done < steps) text += " " + tr("<span style='color:#b00020'>Not every step is ticked: go back and finish them, or enter what is "
                 "actually installed.</span>");
  try {
    const WorkOrder order = makeWorkOrder(state_, *basis_, now);
    text += "<p>" + tr("<b>Expected result</b>") + "<br>" + order.expected.join("<br>") + "</p>";
    const QImage img = renderWorkOrder(order, 96);
    preview_->setPixmap(QPixmap::fromImage(img.scaled(preview_->size() - QSize(2, 2), Qt::KeepAspectRatio,
                                                      Qt::SmoothTransformation)));
  } catch (const InputError& e) {
    save_status_->setText(q(e.what()));
  }
  summary_->setText(text);
}

QString SummaryPage::exportPdf(const QString& path) {
  QString error;
  if (!basis_) {
    error = tr("nothing to export");
  } else {
    try {
      OperatorWizard* w = wiz();
      error = writeWorkOrderPdf(makeWorkOrder(state_, *basis_, w ? w->now() : nowUtc()), path);
    } catch (const InputError& e) {
      error = q(e.what());
    }
  }
  export_status_->setStyleSheet(error.isEmpty() ? "color: #1b5e20;" : "color: #b00020;");
  export_status_->setText(error.isEmpty() ? tr("Work order written to %1").arg(path) : tr("Not exported: %1").arg(error));
  return error;
}

QString SummaryPage::exportJson(const QString& path) {
  OperatorWizard* w = wiz();
  const QString error = basis_ ? writePreMissionJson(state_, *basis_, w ? w->now() : nowUtc(), path) : tr("nothing to export");
  export_status_->setStyleSheet(error.isEmpty() ? "color: #1b5e20;" : "color: #b00020;");
  export_status_->setText(error.isEmpty() ? tr("JSON report written to %1").arg(path) : tr("Not exported: %1").arg(error));
  return error;
}

void SummaryPage::exportWithDialog(bool pdf) {
  QSettings settings;
  const QString dir = settings.value("paths/last_export_folder").toString();
  const QString base = q(state_.configuration_id.empty() ? std::string("plan") : state_.configuration_id);
  const QString file =
      pdf ? QFileDialog::getSaveFileName(this, tr("Export the work order"), dir + "/" + base + "_work_order.pdf",
                                         tr("PDF files (*.pdf)"))
          : QFileDialog::getSaveFileName(this, tr("Export the JSON report"), dir + "/" + base + "_plan.json",
                                         tr("JSON files (*.json)"));
  if (file.isEmpty()) return;
  settings.setValue("paths/last_export_folder", QFileInfo(file).absolutePath());
  if (pdf) {
    exportPdf(file);
  } else {
    exportJson(file);
  }
}

bool SummaryPage::validatePage() {
  // Finish: the session goes into the history as one transaction.
  OperatorWizard* w = wiz();
  if (!basis_ || !state_.plan) return false;
  HistoryStore* store = w ? w->history() : nullptr;
  if (!store) return !w || w->confirmCloseWithoutHistory();
  try {
    savePreMissionToHistory(*store, state_, *basis_, w->now());
  } catch (const InputError& e) {
    save_status_->setText(tr("Not saved: %1").arg(q(e.what())));
    return false;
  }
  w->reportSaved(tr("Saved configuration %1: %2the plan, the next mission's water and the installed state.")
                     .arg(q(state_.configuration_id),
                          state_.mode == SessionMode::kPostMission && state_.log ? tr("the mission log, ") : QString()));
  return true;
}

}  // namespace auv::ui
