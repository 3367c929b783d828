#include "pages/glider_ballast_page.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "common/input_error.h"
#include "history/store.h"
#include "widgets/export_file_dialog.h"
#include "widgets/glider_ballast_map.h"
#include "widgets/inputs.h"
#include "wizard/glider_work_order.h"
#include "wizard/history_save.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

QString bullets(const QStringList& lines) {
  QString html = "<ul style='margin-left: -20px'>";
  for (const QString& l : lines) html += "<li>" + l.toHtmlEscaped() + "</li>";
  return html + "</ul>";
}

}  // namespace

GliderBallastPage::GliderBallastPage(WizardState& state) : state_(state) {
  setTitle(tr("Glider: where the grams go"));
  setSubTitle(tr("What to change on the glider for the next deployment's water. Finish saves the mission to the history."));
  headline_ = new QLabel;
  headline_->setObjectName("glider_headline");
  headline_->setWordWrap(true);
  headline_->setTextFormat(Qt::RichText);
  steps_ = new QLabel;
  steps_->setObjectName("glider_steps");
  steps_->setWordWrap(true);
  steps_->setTextFormat(Qt::RichText);
  steps_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  notes_ = new QLabel;
  notes_->setObjectName("glider_notes");
  notes_->setWordWrap(true);
  notes_->setTextFormat(Qt::RichText);
  map_ = new GliderBallastMap;
  map_->setMinimumHeight(360);
  export_ = new QPushButton(tr("Export work &order (PDF)…"));
  export_->setObjectName("glider_export_pdf");
  export_->setMinimumHeight(32);
  export_->setToolTip(tr("One A4 page: the glider, the target water, the grams per place, the map and a signature line."));
  save_status_ = makeErrorLabel("glider_save_status");
  connect(export_, &QPushButton::clicked, this, [this] {
    const QString path = askExportFile(this, tr("Export the work order"), state_.log_file, "_work_order.pdf", tr("PDF files (*.pdf)"));
    if (path.isEmpty()) return;
    const QString error = exportWorkOrder(path);
    save_status_->setText(error.isEmpty() ? QString() : error);
  });

  auto* content = new QWidget;
  auto* cl = new QVBoxLayout(content);
  cl->setContentsMargins(0, 0, 0, 0);
  cl->addWidget(headline_);
  cl->addWidget(steps_);
  cl->addWidget(map_, 1);
  cl->addWidget(notes_);
  auto* row = new QHBoxLayout;
  row->addWidget(export_);
  row->addStretch();
  cl->addLayout(row);
  cl->addWidget(save_status_);
  // Fits 1366 x 768; a smaller window scrolls.
  auto* scroll = new QScrollArea;
  scroll->setObjectName("glider_scroll");
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(scroll);
}

void GliderBallastPage::initializePage() {
  save_status_->clear();
  const GliderInstructions in = gliderInstructions(state_.glider_plan, state_.vehicle ? &*state_.vehicle : nullptr);
  headline_->setText("<b>" + in.headline.toHtmlEscaped() + "</b><br>" + in.target.toHtmlEscaped());
  steps_->setText(bullets(in.steps));
  QStringList notes;
  for (const QString& c : in.cannot_tell) notes << tr("Cannot tell: %1").arg(c);
  for (const QString& w : in.warnings) notes << tr("Note: %1").arg(w);
  notes_->setText(notes.isEmpty() ? QString() : bullets(notes));
  GliderMapModel m = state_.vehicle ? makeGliderMapModel(*state_.vehicle, state_.glider_plan) : GliderMapModel{};
  // Without the bottles' contents what they hold afterwards is not known.
  if (state_.mission_installed_kg.size() != (state_.vehicle ? state_.vehicle->points.size() : 0))
    for (auto& p : m.places) p.after_g = -1.0;
  map_->setModel(m);
}

QString GliderBallastPage::exportWorkOrder(const QString& path) {
  auto* w = qobject_cast<OperatorWizard*>(wizard());
  try {
    return writeWorkOrderPdf(makeGliderWorkOrder(state_, w ? w->now() : nowUtc()), path);
  } catch (const InputError& e) {
    return q(e.what());
  }
}

bool GliderBallastPage::validatePage() {
  auto* w = qobject_cast<OperatorWizard*>(wizard());
  HistoryStore* store = w ? w->history() : nullptr;
  if (!store) return !w || w->confirmCloseWithoutHistory();
  try {
    saveMissionToHistory(*store, state_, w->now());
  } catch (const InputError& e) {
    save_status_->setText(tr("Not saved: %1").arg(q(e.what())));
    return false;
  }
  w->reportSaved(tr("Saved configuration %1: the mission log, its analysis and the glider's ballast answer.")
                     .arg(q(state_.configuration_id)));
  return true;
}

}  // namespace auv::ui
