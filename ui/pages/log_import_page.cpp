#include "pages/log_import_page.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

#include "widgets/inputs.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

// The reader's problem kinds in words a technician can act on.
QString kindText(ReadProblemKind k) {
  switch (k) {
    case ReadProblemKind::kNotANumber: return LogImportPage::tr("cells that are not numbers");
    case ReadProblemKind::kWrongCellCount: return LogImportPage::tr("rows with the wrong number of cells");
    case ReadProblemKind::kMissingTime: return LogImportPage::tr("rows without a time");
    case ReadProblemKind::kTimeNotIncreasing: return LogImportPage::tr("rows going back in time");
    case ReadProblemKind::kDuplicateTime: return LogImportPage::tr("rows repeating the previous time (merged)");
    case ReadProblemKind::kConflictingDuplicate: return LogImportPage::tr("repeated times with different values");
    case ReadProblemKind::kValueOutOfRange: return LogImportPage::tr("fill values or huge numbers (blanked)");
    case ReadProblemKind::kTruncatedLine: return LogImportPage::tr("a last line cut short");
    case ReadProblemKind::kOverlongLine: return LogImportPage::tr("overlong lines");
    case ReadProblemKind::kCommentAfterHeader: return LogImportPage::tr("comment lines among the rows");
    case ReadProblemKind::kUnitAssumed: return LogImportPage::tr("columns without a unit (unit assumed)");
    case ReadProblemKind::kColumnIgnored: return LogImportPage::tr("columns without a name (ignored)");
    case ReadProblemKind::kDuplicateColumn: return LogImportPage::tr("repeated column names (renamed)");
    case ReadProblemKind::kNoFinalNewline: return LogImportPage::tr("no line end after the last row");
    case ReadProblemKind::kTimeGap: return LogImportPage::tr("long gaps in time");
    case ReadProblemKind::kTimeZoneAssumed: return LogImportPage::tr("times without a zone (UTC assumed)");
    case ReadProblemKind::kCount: break;
  }
  return q(toString(k));
}

QPushButton* button(const QString& text, const char* name, const QString& tip) {
  auto* b = new QPushButton(text);
  b->setObjectName(name);
  b->setToolTip(tip);
  b->setMinimumHeight(32);
  b->setAutoDefault(false);  // Enter means Next in a wizard
  return b;
}

}  // namespace

LogImportPage::LogImportPage(WizardState& state) : state_(state) {
  setTitle(tr("Import the mission log"));
  setSubTitle(tr("Choose the log of the mission, or drop the file onto this page. The format is recognised "
                 "from the content, not the file name."));
  setAcceptDrops(true);
  path_ = new QLineEdit;
  path_->setObjectName("log_path");
  path_->setToolTip(tr("The mission log file: the vehicle's log converted to the mission-log CSV."));
  path_->setMinimumHeight(32);
  browse_ = button(tr("&Browse…"), "browse", tr("Choose the log file."));
  import_ = button(tr("&Import"), "import", tr("Read the file named on the left."));
  progress_ = new QProgressBar;
  progress_->setObjectName("progress");
  progress_->setRange(0, 100);
  progress_->setValue(0);
  progress_->setMinimumHeight(28);
  progress_->setToolTip(tr("How much of the file has been read."));
  cancel_ = button(tr("&Cancel import"), "cancel_import", tr("Stop reading; nothing of this file is kept."));
  cancel_->setEnabled(false);
  drop_hint_ = new QLabel(tr("↓ Drop a log file here ↓"));
  drop_hint_->setObjectName("drop_hint");
  drop_hint_->setAlignment(Qt::AlignCenter);
  drop_hint_->setMinimumHeight(60);
  drop_hint_->setStyleSheet("QLabel { border: 2px dashed #8a8a8a; color: #555; }");
  status_ = new QLabel;
  status_->setObjectName("import_status");
  status_->setWordWrap(true);
  summary_ = new QLabel;
  summary_->setObjectName("import_summary");
  summary_->setWordWrap(true);
  summary_->setTextFormat(Qt::RichText);
  problems_ = new QListWidget;
  problems_->setObjectName("problems");
  problems_->setWordWrap(true);
  problems_->setToolTip(tr("The first problems of each kind, with the line and what to do."));

  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Log file:")));
  row->addWidget(path_, 1);
  row->addWidget(browse_);
  row->addWidget(import_);
  auto* prow = new QHBoxLayout;
  prow->addWidget(progress_, 1);
  prow->addWidget(cancel_);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(row);
  lay->addWidget(drop_hint_);
  lay->addLayout(prow);
  lay->addWidget(status_);
  lay->addWidget(summary_);
  lay->addWidget(problems_, 1);

  connect(browse_, &QPushButton::clicked, this, [this] { browse(); });
  connect(import_, &QPushButton::clicked, this, [this] { startImport(path_->text()); });
  connect(path_, &QLineEdit::returnPressed, this, [this] { startImport(path_->text()); });
  connect(cancel_, &QPushButton::clicked, this, [this] {
    job_.cancel();
    status_->setText(tr("Cancelling…"));
  });
  connect(&job_, &LogImportJob::progress, progress_, &QProgressBar::setValue);
  connect(&job_, &LogImportJob::finished, this, [this](const LogImportOutcome& o) { onFinished(o); });
}

void LogImportPage::initializePage() {
  path_->setText(q(state_.log_file));
  // A resumed or demo session names its log but has not read it yet.
  if (!state_.log && !state_.log_file.empty() && !job_.running()) {
    startImport(q(state_.log_file));
  } else {
    showSummary();
  }
}

void LogImportPage::browse() {
  QSettings settings;
  const QString dir = settings.value("paths/last_log_folder").toString();
  const QString file = QFileDialog::getOpenFileName(this, tr("Mission log"), dir,
                                                    tr("Mission logs (*.csv *.txt *.log);;All files (*)"));
  if (!file.isEmpty()) startImport(file);
}

void LogImportPage::dragEnterEvent(QDragEnterEvent* e) {
  const auto urls = e->mimeData()->urls();
  if (urls.size() == 1 && urls.first().isLocalFile()) e->acceptProposedAction();
}

void LogImportPage::dropEvent(QDropEvent* e) {
  const auto urls = e->mimeData()->urls();
  if (urls.size() == 1 && urls.first().isLocalFile()) {
    startImport(urls.first().toLocalFile());
    e->acceptProposedAction();
  }
}

void LogImportPage::startImport(const QString& path) {
  if (job_.running() || path.trimmed().isEmpty()) return;
  path_->setText(path);
  QSettings().setValue("paths/last_log_folder", QFileInfo(path).absolutePath());
  state_.log.reset();
  state_.log_report.reset();
  state_.log_format.clear();
  state_.log_file = path.toStdString();
  summary_->clear();
  problems_->clear();
  status_->setStyleSheet(QString());
  status_->setText(tr("Reading %1…").arg(QFileInfo(path).fileName()));
  progress_->setValue(0);
  cancel_->setEnabled(true);
  import_->setEnabled(false);
  browse_->setEnabled(false);
  emit completeChanged();
  job_.start(path);
}

void LogImportPage::onFinished(const LogImportOutcome& out) {
  cancel_->setEnabled(false);
  import_->setEnabled(true);
  browse_->setEnabled(true);
  switch (out.status) {
    case LogImportOutcome::Status::kOk:
      state_.log = out.log;
      state_.log_report = out.report;
      state_.log_format = out.format;
      progress_->setValue(100);
      status_->setText(tr("Read completely."));
      break;
    case LogImportOutcome::Status::kCancelled:
      status_->setStyleSheet("color: #8a6d00;");
      status_->setText(tr("Import cancelled at %1 %; nothing of this file was kept.").arg(progress_->value()));
      break;
    case LogImportOutcome::Status::kFailed:
      status_->setStyleSheet("color: #b00020;");
      status_->setText(tr("Cannot read this file: %1").arg(q(out.error)));
      break;
  }
  showSummary();
  emit completeChanged();
}

void LogImportPage::showSummary() {
  problems_->clear();
  if (!state_.log || !state_.log_report) {
    summary_->clear();
    return;
  }
  const MissionLog& log = *state_.log;
  const ReadReport& r = *state_.log_report;
  QStringList plotted;
  for (const char* name : {"depth", "depth_cmd", "pitch", "pitch_cmd", "roll"}) {
    plotted << QString("%1 %2").arg(name, log.has(name) ? "✓" : "✗");
  }
  QStringList why;
  for (int k = 0; k < static_cast<int>(ReadProblemKind::kCount); ++k) {
    const auto kind = static_cast<ReadProblemKind>(k);
    if (r.count(kind) > 0) why << tr("%1 × %2").arg(r.count(kind)).arg(kindText(kind));
  }
  summary_->setText(
      tr("<b>%1</b> (%2): <b>%3 rows</b> × <b>%4 channels</b> over %5 h. Skipped %6 rows, merged %7, blanked %8 "
         "cells.<br>Plotted channels: %9<br>%10")
          .arg(QFileInfo(q(state_.log_file)).fileName().toHtmlEscaped(), q(state_.log_format).toHtmlEscaped())
          .arg(r.rows_kept)
          .arg(log.channels.size())
          .arg(log.duration() / 3600.0, 0, 'f', 2)
          .arg(r.rows_skipped)
          .arg(r.rows_merged)
          .arg(r.cells_blanked)
          .arg(plotted.join("  "))
          .arg(why.isEmpty() ? tr("Nothing was skipped or changed.") : tr("Why: %1.").arg(why.join("; ").toHtmlEscaped())));
  // The file is named above: each problem starts with just its name.
  const QString full = q(state_.log_file), name = QFileInfo(full).fileName();
  for (const auto& p : r.problems) problems_->addItem(q(p.text()).replace(full, name));
}

bool LogImportPage::isComplete() const { return state_.log != nullptr && !job_.running(); }

bool LogImportPage::validatePage() { return isComplete(); }

int LogImportPage::nextId() const { return OperatorWizard::kDeviationPlots; }

}  // namespace auv::ui
