#include "pages/log_import_page.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QUrl>
#include <QVBoxLayout>
#include <algorithm>

#include "common/input_error.h"
#include "missionlog/delimited_text_reader.h"
#include "missionlog/log_reader.h"
#include "widgets/column_mapping_dialog.h"
#include "widgets/inputs.h"
#include "wizard/installed_from_log.h"
#include "wizard/column_mapping_store.h"
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

// Text a person could map by hand: no NUL bytes, a header and a row.
bool looksLikeText(const QString& path) {
  try {
    const std::string head = readFirstBytes(path.toStdString(), 4096);
    if (head.find('\0') != std::string::npos) return false;
    return std::count(head.begin(), head.end(), '\n') >= 1;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

LogImportPage::LogImportPage(WizardState& state) : state_(state) {
  setTitle(tr("Import the mission log"));
  setSubTitle(tr("Choose the log of the mission, or drop the file onto this page. The format is recognised "
                 "from the content, not the file name."));
  setAcceptDrops(true);
  path_ = new QLineEdit;
  path_->setObjectName("log_path");
  path_->setToolTip(tr("The mission log: a file, several files of one mission separated by \"; \", or the "
                       "folder the vehicle's files are in (type or paste it, or drop the folder here)."));
  path_->setMinimumHeight(32);
  browse_ = button(tr("B&rowse…"), "browse",
                   tr("Choose the log file, or several files of one mission (they are merged on time)."));

  import_ = button(tr("&Import"), "import", tr("Read the file named on the left."));
  map_ = button(tr("&Map columns…"), "map_columns",
                tr("Say which column of a vendor text log is the time, the depth, the pitch… and read it again."));
  installed_box_ = new QGroupBox(tr("Adjustment weight installed &during this mission"));
  installed_box_->setObjectName("installed_box");
  installed_box_->setToolTip(tr("The kit pieces that were in the vehicle while it flew this log, per point. "
                                "The analysis needs the weight the vehicle flew with."));
  installed_grid_ = new QGridLayout(installed_box_);
  installed_grid_->setContentsMargins(8, 4, 8, 4);
  installed_grid_->setVerticalSpacing(2);
  alignment_ = makeNumber("pitch_alignment_sigma_deg", 0.0, kMaxPitchAlignmentDeg, 2, tr(" °"),
                          tr("How closely the pitch sensor reads the hull's pitch, from a level check on the dock "
                             "(the hull level, the reading compared). The analysis finds the sensor's offset from "
                             "the log either way; a checked sensor lets it narrow the net buoyancy and CG. Leave "
                             "\"not checked\" when nobody checked it: the analysis then allows up to a degree."));
  alignment_->setSpecialValueText(tr("not checked"));
  alignment_->setMinimumWidth(130);
  error_ = makeErrorLabel();  // a field's problem on Next (OperatorWizard::validateCurrentPage)
  alignment_row_ = new QWidget;
  auto* arow = new QHBoxLayout(alignment_row_);
  arow->setContentsMargins(8, 0, 8, 0);
  auto* alabel = new QLabel(tr("&Pitch sensor level check, within ±"));
  alabel->setBuddy(alignment_->lineEdit());
  arow->addWidget(alabel);
  arow->addWidget(alignment_);
  arow->addStretch(1);
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
  row->addWidget(map_);
  auto* prow = new QHBoxLayout;
  prow->addWidget(progress_, 1);
  prow->addWidget(cancel_);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(row);
  lay->addWidget(drop_hint_);
  lay->addLayout(prow);
  lay->addWidget(status_);
  lay->addWidget(installed_box_);
  lay->addWidget(alignment_row_);
  lay->addWidget(error_);
  lay->addWidget(summary_);
  lay->addWidget(problems_, 1);
  // Shown only with something in it: an empty white box under "Nothing was
  // skipped" read as a chart that failed to draw (found under Xvfb).
  problems_->hide();
  lay->addStretch(0);

  connect(browse_, &QPushButton::clicked, this, [this] { browse(); });
  connect(import_, &QPushButton::clicked, this, [this] { startImport(path_->text()); });
  connect(map_, &QPushButton::clicked, this, [this] { openMappingDialog(); });
  connect(path_, &QLineEdit::returnPressed, this, [this] { startImport(path_->text()); });
  connect(cancel_, &QPushButton::clicked, this, [this] {
    job_.cancel();
    status_->setText(tr("Cancelling…"));
  });
  connect(&job_, &LogImportJob::progress, progress_, &QProgressBar::setValue);
  connect(&job_, &LogImportJob::finished, this, [this](const LogImportOutcome& o) { onFinished(o); });
}

void LogImportPage::buildInstalledInputs() {
  const std::string id = state_.vehicle ? state_.vehicle->id : std::string();
  // A glider's fit does not use it (its ballast state is fitted whole).
  installed_box_->setVisible(state_.vehicle && !state_.isGlider());
  alignment_row_->setVisible(state_.vehicle && !state_.isGlider());
  if (id == installed_vehicle_ && installed_.size() == (state_.vehicle ? state_.vehicle->points.size() : 0u)) return;
  installed_vehicle_ = id;
  for (NumberInput* sb : installed_) delete sb;
  installed_.clear();
  while (QLayoutItem* item = installed_grid_->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  if (!state_.vehicle) return;
  const auto& pts = state_.vehicle->points;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    auto* sb = makeNumber(QString("installed_%1").arg(q(pts[i].name)), 0.0, std::max(pts[i].capacity_kg, 1.0), 2,
                        tr(" kg"),
                        tr("Kit pieces at %1 during the logged mission, kg (what was installed before it flew, "
                           "not a planned change).").arg(q(pts[i].label)));
    auto* label = new QLabel(q(pts[i].label) + ":");
    label->setBuddy(sb);
    const int r = static_cast<int>(i / 2), c = static_cast<int>(i % 2) * 2;
    sb->setMinimumWidth(130);
    installed_grid_->addWidget(label, r, c);
    installed_grid_->addWidget(sb, r, c + 1);
    installed_.push_back(sb);
  }
  installed_grid_->setColumnMinimumWidth(2, 0);
  installed_grid_->setColumnStretch(4, 1);
}

std::vector<double> LogImportPage::installedKg() const {
  std::vector<double> out;
  for (const NumberInput* sb : installed_) out.push_back(sb->value());
  return out;
}

void LogImportPage::initializePage() {
  buildInstalledInputs();
  // The mission's own entry if there is one, else what the start page took
  // from the history (or the first-mission input), else nothing.
  const std::size_t n = installed_.size();
  const std::vector<double>& from = state_.mission_installed_kg.size() == n ? state_.mission_installed_kg
                                    : state_.crane.installed_kg.size() == n ? state_.crane.installed_kg
                                                                            : std::vector<double>(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) installed_[i]->setValue(from[i]);
  alignment_->setValue(state_.pitch_alignment_sigma_deg.value_or(0.0));
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
  const QStringList files = QFileDialog::getOpenFileNames(
      this, tr("Mission log"), dir,
      tr("Mission logs (*.csv *.txt *.log *.dat *.asc *.dba *.nc *.gz *.dbd *.ebd *.sbd *.tbd *.mbd *.nbd *.dcd *.ecd "
         "*.scd *.tcd *.mcd *.ncd);;All files (*)"));
  // Several files of one mission travel as one path list (LogImportJob splits it).
  if (!files.isEmpty()) startImport(files.join(kLogPathSeparator));
}

void LogImportPage::dragEnterEvent(QDragEnterEvent* e) {
  const auto urls = e->mimeData()->urls();
  if (!urls.isEmpty() && std::all_of(urls.begin(), urls.end(), [](const QUrl& u) { return u.isLocalFile(); }))
    e->acceptProposedAction();
}

void LogImportPage::dropEvent(QDropEvent* e) {
  const auto urls = e->mimeData()->urls();
  QStringList files;
  for (const QUrl& u : urls)
    if (u.isLocalFile()) files << u.toLocalFile();
  if (!files.isEmpty() && files.size() == urls.size()) {
    startImport(files.join(kLogPathSeparator));
    e->acceptProposedAction();
  }
}

void LogImportPage::startImport(const QString& path, std::optional<ColumnMapping> mapping) {
  if (job_.running() || path.trimmed().isEmpty()) return;
  QString mapping_note;
  if (!mapping && state_.vehicle) {
    QString problem;
    mapping = loadSavedColumnMapping(state_.vehicle->id, &problem);
    if (!problem.isEmpty()) mapping_note = tr("The saved column mapping is damaged and was not used: %1").arg(problem);
  }
  path_->setText(path);
  const QStringList paths = splitLogPaths(path);
  const QFileInfo first(paths.value(0, path));
  QSettings().setValue("paths/last_log_folder", first.isDir() ? first.absoluteFilePath() : first.absolutePath());
  state_.log.reset();
  state_.log_report.reset();
  state_.log_format.clear();
  state_.analysis.reset();
  state_.model_check.reset();
  // Term choices belong to one log (a resumed session re-reads the same file).
  if (path.toStdString() != state_.log_file) state_.accepted_terms.clear();
  state_.log_file = path.toStdString();
  summary_->clear();
  problems_->clear();
  problems_->hide();
  status_->setStyleSheet(QString());
  status_->setText(tr("Reading %1…").arg(paths.size() > 1 ? tr("%1 and %2 more").arg(first.fileName()).arg(paths.size() - 1)
                                                           : first.fileName()) +
                   (mapping_note.isEmpty() ? QString() : "\n" + mapping_note));
  progress_->setValue(0);
  cancel_->setEnabled(true);
  import_->setEnabled(false);
  browse_->setEnabled(false);
  map_->setEnabled(false);
  emit completeChanged();
  job_.start(path, std::move(mapping));
}

void LogImportPage::onFinished(const LogImportOutcome& out) {
  cancel_->setEnabled(false);
  import_->setEnabled(true);
  browse_->setEnabled(true);
  map_->setEnabled(true);
  bool ask_mapping = false;
  switch (out.status) {
    case LogImportOutcome::Status::kOk:
      state_.log = out.log;
      state_.log_report = out.report;
      state_.log_format = out.format;
      progress_->setValue(100);
      status_->setText(out.mapped ? tr("Read completely with the column mapping.") : tr("Read completely."));
      prefillInstalledFromLog();
      // Vendor text without anything to analyse: the columns were not recognised.
      if (!out.mapped && out.format == DelimitedTextReader().formatName() && !out.log->has("depth") &&
          !out.log->has("pressure")) {
        status_->setText(tr("Read, but no depth or pressure column was recognised: say which column is which."));
        ask_mapping = true;
      }
      break;
    case LogImportOutcome::Status::kCancelled:
      status_->setStyleSheet("color: #8a6d00;");
      status_->setText(tr("Import cancelled at %1 %; nothing of this file was kept.").arg(progress_->value()));
      break;
    case LogImportOutcome::Status::kFailed:
      status_->setStyleSheet("color: #b00020;");
      status_->setText(tr("Cannot read this file: %1").arg(q(out.error)));
      ask_mapping = looksLikeText(path_->text());
      break;
  }
  showSummary();
  emit completeChanged();
  if (ask_mapping) openMappingDialog();
}

ColumnMappingDialog* LogImportPage::mappingDialog() const { return mapping_dialog_.data(); }

void LogImportPage::openMappingDialog() {
  const QString file = path_->text().trimmed();
  if (file.isEmpty() || job_.running()) return;
  if (mapping_dialog_) mapping_dialog_->deleteLater();
  const std::string vehicle = state_.vehicle ? state_.vehicle->id : std::string();
  mapping_dialog_ = new ColumnMappingDialog(file, vehicle, vehicle.empty() ? std::nullopt : loadSavedColumnMapping(vehicle), this);
  connect(mapping_dialog_, &QDialog::accepted, this, [this] { mappingAccepted(); });
  mapping_dialog_->open();
}

void LogImportPage::mappingAccepted() {
  ColumnMappingDialog* dlg = mapping_dialog_;
  if (!dlg) return;
  const ColumnMapping m = dlg->mapping();
  QString saved;
  if (dlg->saveForVehicle() && state_.vehicle) {
    try {
      saveColumnMapping(state_.vehicle->id, m);
    } catch (const InputError& e) {
      saved = tr("The mapping could not be saved: %1").arg(q(e.what()));
    }
  }
  startImport(path_->text(), m);
  if (!saved.isEmpty()) status_->setText(status_->text() + "\n" + saved);
}

void LogImportPage::showSummary() {
  problems_->clear();
  problems_->hide();
  if (!state_.log || !state_.log_report) {
    summary_->clear();
    return;
  }
  const MissionLog& log = *state_.log;
  const ReadReport& r = *state_.log_report;
  QStringList plotted;
  const std::pair<const char*, QString> channels[] = {{"depth", tr("depth")},
                                                       {"depth_cmd", tr("commanded depth")},
                                                       {"pitch", tr("pitch")},
                                                       {"pitch_cmd", tr("commanded pitch")},
                                                       {"roll", tr("roll")}};
  for (const auto& [name, label] : channels) plotted << QString("%1 %2").arg(label, log.has(name) ? "✓" : "✗");
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
          .arg(fixed(log.duration() / 3600.0, 2))
          .arg(r.rows_skipped)
          .arg(r.rows_merged)
          .arg(r.cells_blanked)
          .arg(plotted.join("  "))
          .arg(why.isEmpty() ? tr("Nothing was skipped or changed.") : tr("Why: %1.").arg(why.join("; ").toHtmlEscaped())));
  // The file is named above: each problem starts with just its name.
  const QString full = q(state_.log_file), name = QFileInfo(full).fileName();
  for (const auto& p : r.problems) problems_->addItem(q(p.text()).replace(full, name));
  problems_->setVisible(problems_->count() > 0);
}

bool LogImportPage::isComplete() const { return state_.log != nullptr && !job_.running(); }

void LogImportPage::prefillInstalledFromLog() {
  // The history (or this session) said what was installed: that wins.
  if (!state_.vehicle || installed_.empty()) return;
  for (auto* in : installed_)
    if (in->value() != 0.0) return;
  const auto kg = installedFromLogHeader(*state_.log, *state_.vehicle);
  if (!kg) return;
  for (std::size_t i = 0; i < installed_.size(); ++i) installed_[i]->setValue((*kg)[i]);
  status_->setText(status_->text() + "\n" +
                   tr("Installed masses taken from the log's configuration line; check them below."));
}

bool LogImportPage::validatePage() {
  if (!isComplete()) return false;
  // All zero is possible but rarely true: the analysis would blame the
  // missing ballast on the vehicle. Ask before going on.
  if (installed_box_->isVisible() && !installed_.empty()) {
    bool all_zero = true;
    for (auto* in : installed_) all_zero = all_zero && in->value() == 0.0;
    auto* w = qobject_cast<OperatorWizard*>(wizard());
    if (all_zero && w &&
        !w->ask(tr("Nothing installed?"),
                tr("Every installed mass is 0 kg. If adjustment weights were in the vehicle during this mission, "
                   "enter them under \"Adjustment weight installed during this mission\" first: the analysis would otherwise put "
                   "their weight into the vehicle's own balance. Analyse with nothing installed?"),
                true))
      return false;
  }
  error_->clear();  // a field's problem (OperatorWizard::validateCurrentPage) is fixed once we get here
  // The analysis and the model check follow from the log and this input;
  // the next pages compute them again.
  state_.mission_installed_kg = installedKg();
  const double checked = alignment_->value();
  state_.pitch_alignment_sigma_deg =
      checked >= kMinPitchAlignmentDeg ? std::optional<double>(checked) : std::nullopt;
  state_.analysis.reset();
  state_.model_check.reset();
  return true;
}

int LogImportPage::nextId() const { return OperatorWizard::kDeviationPlots; }

}  // namespace auv::ui
