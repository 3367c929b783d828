#include "pages/model_check_page.h"

#include "wizard/model_words.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGraphicsLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/input_error.h"
#include "discrepancy/profile_update.h"
#include "history/store.h"
#include "plot/min_max_decimation.h"
#include "plot/nice_axis.h"
#include "widgets/calibration_table.h"
#include "widgets/estimate_text.h"
#include "widgets/inputs.h"
#include "wizard/history_save.h"
#include "vehicle/json_reader.h"
#include "vehicle/vehicle_catalog.h"
#include "wizard/operator_wizard.h"
#include "wizard/pre_mission_inputs.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }
// Term values span 1e-6 (compressibility per dbar) to tens: significant digits.
QString sig(double v, int digits) { return significant(v, digits); }

constexpr int kOverlayBuckets = 900;

}  // namespace

ModelCheckPage::ModelCheckPage(WizardState& state) : state_(state) {
  setTitle(tr("Model check: what the model leaves out"));
  setSubTitle(tr("The recording is compared with the vehicle model replaying the mission. Physics the model lacks "
                 "is named, fitted and kept only if it also improves data it was not fitted on."));
  busy_ = new QProgressBar;
  busy_->setObjectName("busy");
  busy_->setRange(0, 0);  // indeterminate: the core check reports no progress
  busy_->setMaximumHeight(18);
  busy_->setTextVisible(false);
  busy_->setToolTip(tr("The model check is running (about a second for a few hours of log)."));
  status_ = new QLabel;
  status_->setObjectName("check_status");
  status_->setWordWrap(true);
  summary_ = new QLabel;
  summary_->setObjectName("check_summary");
  summary_->setWordWrap(true);
  summary_->setTextFormat(Qt::RichText);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  channel_ = new QComboBox;
  channel_->setObjectName("overlay_channel");
  channel_->setMinimumHeight(32);
  channel_->setToolTip(tr("The channel shown: recorded, the model with its ballast state only, and with the "
                          "accepted terms. The one the model misses most is chosen first."));
  channel_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  channel_->setMinimumWidth(240);
  auto* channel_label = new QLabel(tr("Sho&w:"));
  channel_label->setBuddy(channel_);
  difference_ = new QCheckBox(tr("the &difference recorded − model"));
  difference_->setObjectName("show_difference");
  difference_->setToolTip(tr("Plot recorded minus model (with the ballast state only, and with the accepted "
                             "terms) instead of the values: small misfits become visible."));

  chart_ = new QChart;
  chart_->setAnimationOptions(QChart::NoAnimation);
  chart_->setBackgroundRoundness(0);
  chart_->layout()->setContentsMargins(0, 0, 0, 0);
  chart_->setMargins(QMargins(4, 2, 12, 2));
  chart_->legend()->setAlignment(Qt::AlignTop);
  x_ = new QValueAxis;
  x_->setTitleText(tr("time since start [min]"));
  x_->setLabelFormat("%.0f");
  x_->setTickType(QValueAxis::TicksDynamic);
  x_->setTickAnchor(0.0);
  y_ = new QValueAxis;
  y_->setLabelFormat("%.1f");
  chart_->addAxis(x_, Qt::AlignBottom);
  chart_->addAxis(y_, Qt::AlignLeft);
  const QString names[3] = {tr("recorded"), tr("model, ballast state only"), tr("model with the accepted terms")};
  const QColor colours[3] = {QColor(31, 119, 180), QColor(230, 120, 20), QColor(44, 160, 44)};
  for (std::size_t i = 0; i < 3; ++i) {
    auto* s = new QLineSeries;
    s->setName(names[i]);
    QPen pen(colours[i]);
    pen.setWidth(i == 0 ? 1 : 2);
    s->setPen(pen);
    chart_->addSeries(s);
    s->attachAxis(x_);
    s->attachAxis(y_);
    series_[i] = s;
  }
  chart_view_ = new QChartView(chart_);
  chart_view_->setObjectName("overlay_chart");
  chart_view_->setRenderHint(QPainter::Antialiasing, false);
  chart_view_->setMinimumHeight(200);

  terms_ = new QTableWidget(0, 3);
  terms_->setObjectName("terms");
  terms_->setHorizontalHeaderLabels({tr("Accept: term"), tr("Value ± σ"), tr("Held-out RMS without → with")});
  terms_->verticalHeader()->hide();
  terms_->verticalHeader()->setDefaultSectionSize(24);
  terms_->horizontalHeader()->setStretchLastSection(true);
  terms_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  terms_->setSelectionMode(QAbstractItemView::SingleSelection);
  terms_->setToolTip(tr("Physics the model lacks, best first. Tick a term to accept it (Space toggles the "
                        "selected row); accepted terms go into the vehicle model for the next mission."));
  QScrollArea* scroll = makeMessageArea("where", &where_, Qt::RichText);
  calibration_ = new CalibrationTable;
  calibration_->setObjectName("check_calibration");
  save_status_ = makeErrorLabel("save_status");

  auto* top = new QHBoxLayout;
  top->addWidget(status_, 1);
  top->addWidget(busy_, 1);
  auto* crow = new QHBoxLayout;
  crow->addWidget(channel_label);
  crow->addWidget(channel_);
  crow->addSpacing(12);
  crow->addWidget(difference_);
  crow->addStretch(1);
  auto* bottom = new QHBoxLayout;
  // Left: the terms to accept over what was calibrated; right: where.
  auto* left = new QVBoxLayout;
  left->addWidget(terms_, 2);
  left->addWidget(calibration_, 3);
  bottom->addLayout(left, 3);
  bottom->addWidget(scroll, 2);
  auto* lay = new QVBoxLayout(this);
  lay->setSpacing(4);
  lay->addLayout(top);
  lay->addWidget(summary_);
  lay->addLayout(crow);
  lay->addWidget(chart_view_, 2);
  lay->addLayout(bottom, 2);
  lay->addWidget(save_status_);
  setTabOrder(channel_, difference_);
  setTabOrder(difference_, terms_);
  connect(difference_, &QCheckBox::toggled, this, [this](bool on) { setShowDifference(on); });

  connect(&job_, &ModelCheckJob::finished, this, [this](const ModelCheckOutcome& o) { onFinished(o); });
  connect(channel_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (filling_) return;
    showChannel(channel_->itemData(i).toInt());
    if (outcome_.ok) showWhere();
  });
  connect(terms_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    if (!filling_ && item->column() == 0) updateAccepted();
  });
}

int ModelCheckPage::nextId() const {
  // The pre-mission page comes from another part of the wizard; until it is
  // there, this page ends the post-mission sequence.
  const QWizard* w = wizard();
  // Gliders: the target water and grams per bottle (or lead and C_VBD).
  if (state_.isGlider() && w && w->page(OperatorWizard::kGliderPreMission)) return OperatorWizard::kGliderPreMission;
  return w && w->page(OperatorWizard::kPreMission) ? OperatorWizard::kPreMission : -1;
}

bool ModelCheckPage::isComplete() const { return !job_.running(); }

void ModelCheckPage::initializePage() {
  save_status_->clear();
  // Back and forward again over the same log: the result is still valid.
  if (state_.model_check && outcome_.ok && outcome_.log == state_.log) {
    showResult();
    return;
  }
  outcome_ = ModelCheckOutcome{};
  state_.model_check.reset();
  state_.check_model.reset();
  showResult();
  if (!state_.log || !state_.vehicle) {
    status_->setText(tr("No log imported: go back to the import page."));
    return;
  }
  if (job_.running()) return;
  discrepancy::CheckSetup setup;
  if (!state_.isGlider() && state_.mission_installed_kg.size() == state_.vehicle->points.size())
    setup.auv.installed_kg = state_.mission_installed_kg;
  status_->setText(tr("Checking the model against the recording…"));
  busy_->setVisible(true);
  // Against the configuration's model as it was before this session's
  // terms (a new log after going back must not see them twice).
  VehicleProfile base = *state_.vehicle;
  try {
    base = configurationVehicle();
  } catch (const InputError&) {
    // The session's vehicle, e.g. a profile file that is not in the catalog.
  }
  job_.start(state_.log, base, state_.resource_dir, setup, {}, state_.analysis);
  emit completeChanged();
}

void ModelCheckPage::onFinished(const ModelCheckOutcome& out) {
  outcome_ = out;
  if (out.ok && out.result && out.log == state_.log) {
    state_.model_check = out.result;
    state_.check_model = out.model;
    // Choices made on this log stay; a resumed session brings its own; else
    // the terms the check accepted are ticked.
    std::vector<std::string> kept;
    const bool keep = decided_for_ == out.log || !state_.accepted_terms.empty();
    for (const auto& m : out.result->missing_physics) {
      const bool was = std::find(state_.accepted_terms.begin(), state_.accepted_terms.end(), m.id) != state_.accepted_terms.end();
      if (!keep || was) kept.push_back(m.id);
    }
    state_.accepted_terms = kept;
    decided_for_ = out.log;
  }
  showResult();
  emit completeChanged();
}

void ModelCheckPage::showResult() {
  const bool running = job_.running();
  busy_->setVisible(running);
  filling_ = true;
  channel_->clear();
  filling_ = false;
  if (running) return;
  if (!outcome_.ok) {
    summary_->clear();
    terms_->setRowCount(0);
    where_->clear();
    for (auto* s : series_) s->clear();
    chart_->setTitle(QString());
    if (!outcome_.error.empty()) {
      status_->setStyleSheet("color: #b00020;");
      status_->setText(tr("The model check cannot run on this log: %1").arg(q(outcome_.error)));
    }
    return;
  }
  status_->setStyleSheet(QString());
  const auto& r = *outcome_.result;
  status_->setText(tr("Model: %1.").arg(readableModelMessage(outcome_.description)));
  showSummary();
  calibration_->showRows(CalibrationTable::rowsOf(r.calibration));
  const auto& ov = outcome_.overlay;
  filling_ = true;
  for (std::size_t i = 0; i < ov.channels.size(); ++i) {
    const auto& c = ov.channels[i];
    if (c.scored == 0) continue;
    QString name = tr("%1 [%2]").arg(channelLabel(c.channel), q(c.unit));
    if (i == ov.largest) name += tr(" - largest mismatch");
    channel_->addItem(name, static_cast<int>(i));
  }
  filling_ = false;
  if (channel_->count() > 0) {
    channel_->setCurrentIndex(std::max(0, channel_->findData(static_cast<int>(ov.largest))));
    showChannel(channel_->currentData().toInt());
  }
  showTerms();
  showWhere();
}

void ModelCheckPage::showSummary() {
  const auto& r = *outcome_.result;
  // The ballast state the plan uses (the same as on the analysis page and
  // the plan), with the check's own ballast-only fit for comparison.
  const auto e = sessionEstimate(state_);
  const bool g = state_.isGlider();
  QString s = tr("%1 samples in %2 dives/legs.").arg(r.samples).arg(r.units);
  if (e) {
    const analysis::AnalysisReport& a = e->report;
    s += " " + tr("Ballast state: net buoyancy <b>%1</b>, CG − CB x <b>%2</b>, y <b>%3</b> (model ballast state "
                  "alone: %4 kg).")
                   .arg(EstimateText::of(a.net_buoyancy_kg, g ? 3 : 2, tr(" kg")),
                        EstimateText::of(a.cg_x_mm, 2, tr(" mm")), EstimateText::of(a.cg_y_mm, 2, tr(" mm")),
                        fixed(r.net_buoyancy_base_kg, g ? 3 : 2));
    s += "<br>" + EstimateText::planUses(e->source);
    // The check's fit is adopted with its difference from the analysis in
    // the sigma (discrepancy::planEstimate): said, so the wider margin on
    // the adjustment page is not a surprise.
    const analysis::EstimatedValue& before = state_.analysis->net_buoyancy_kg;
    if (e->source == discrepancy::EstimateSource::kModelCheck && before.known &&
        std::abs(a.net_buoyancy_kg.value - before.value) > before.sigma)
      s += " " + tr("The check's fit and the analysis (%1) differ by %2 kg: the uncertainty includes that difference, "
                    "so the plan's safety margin covers both.")
                     .arg(EstimateText::of(before, g ? 3 : 2, tr(" kg")),
                          fixed(std::abs(a.net_buoyancy_kg.value - before.value), g ? 3 : 2));
  } else {
    s += " " + tr("Net buoyancy with the accepted terms <b>%1</b> (ballast state alone: %2 kg).")
                   .arg(EstimateText::valueSigma(true, r.net_buoyancy_kg, r.net_buoyancy_sigma_kg, 3, tr(" kg")),
                        fixed(r.net_buoyancy_base_kg, 3));
  }
  summary_->setText(s);
}

int ModelCheckPage::shownChannel() const { return channel_->count() > 0 ? channel_->currentData().toInt() : -1; }

void ModelCheckPage::showChannel(int index) {
  const auto& ov = outcome_.overlay;
  if (index < 0 || index >= static_cast<int>(ov.channels.size())) return;
  const int combo = channel_->findData(index);
  if (combo >= 0 && combo != channel_->currentIndex()) {
    filling_ = true;
    channel_->setCurrentIndex(combo);
    filling_ = false;
  }
  const auto& c = ov.channels[static_cast<std::size_t>(index)];
  std::vector<double> t_min(ov.t_s.size());
  std::transform(ov.t_s.begin(), ov.t_s.end(), t_min.begin(), [](double t) { return t / 60.0; });
  const bool diff = difference_->isChecked();
  const std::vector<double>* v[3] = {&c.recorded, &c.simulated_before, &c.simulated_after};
  double t0 = INFINITY, t1 = -INFINITY, lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < t_min.size(); ++i) {
    if (std::isnan(c.simulated_before[i])) continue;  // plot the scored rows only
    t0 = std::min(t0, t_min[i]);
    t1 = std::max(t1, t_min[i]);
  }
  if (!(t1 > t0)) return;
  for (std::size_t k = 0; k < 3; ++k) {
    series_[k]->setVisible(!(diff && k == 0));
    if (diff && k == 0) {
      series_[k]->clear();
      continue;
    }
    std::vector<double> y(v[k]->size());
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double yi = std::isnan(c.simulated_before[i]) ? NAN : (*v[k])[i];
      y[i] = diff ? c.recorded[i] - yi : yi;
    }
    const auto pts = decimateMinMax(t_min, y, t0, t1, kOverlayBuckets);
    QList<QPointF> list;
    list.reserve(static_cast<qsizetype>(pts.size()));
    for (const auto& p : pts) {
      list.append(QPointF(p.x, p.y));
      lo = std::min(lo, p.y);
      hi = std::max(hi, p.y);
    }
    series_[k]->replace(list);
  }
  x_->setRange(t0, t1);
  const NiceAxis ticks = niceAxis(t0, t1, 6);
  x_->setTickInterval(ticks.step);
  x_->setLabelFormat(ticks.step >= 1.0 ? QString("%.0f") : QString("%.1f"));
  if (std::isfinite(lo) && std::isfinite(hi)) {
    const NiceAxis a = niceAxis(lo, hi);
    y_->setRange(a.min, a.max);
    y_->setTickCount(a.ticks);
  }
  const bool depth = c.channel == discrepancy::Channel::kDepth;
  y_->setReverse(depth && !diff);
  y_->setTitleText(diff ? tr("difference [%1]").arg(q(c.unit))
                        : tr("%1 [%2]").arg(channelLabel(c.channel), q(c.unit)));
  series_[1]->setName(diff ? tr("recorded − model, ballast state only") : tr("model, ballast state only"));
  series_[2]->setName(diff ? tr("recorded − model with the accepted terms") : tr("model with the accepted terms"));
  chart_->setTitle(tr("%1: RMS recorded − model %2 → %3 %4 (ballast state only → with the accepted terms)")
                       .arg(channelLabel(c.channel), sig(c.rms_before, 3), sig(c.rms_after, 3), q(c.unit)));
}

void ModelCheckPage::setShowDifference(bool on) {
  if (difference_->isChecked() != on) {
    difference_->setChecked(on);  // toggled -> here again
    return;
  }
  showChannel(shownChannel());
}

int ModelCheckPage::pointsDrawn(int series) const {
  return static_cast<int>(series_[static_cast<std::size_t>(series)]->count());
}

void ModelCheckPage::showTerms() {
  filling_ = true;
  terms_->setRowCount(0);
  const auto& found = outcome_.result->missing_physics;
  if (found.empty()) {
    terms_->setRowCount(1);
    auto* item = new QTableWidgetItem(tr("No missing physics found: the model with its ballast state explains "
                                         "this log within its noise."));
    terms_->setItem(0, 0, item);
    terms_->setSpan(0, 0, 1, 3);
  }
  for (const auto& m : found) {
    const int r = terms_->rowCount();
    terms_->insertRow(r);
    auto* name = new QTableWidgetItem(termLabel(m.id));
    name->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
    const bool on = std::find(state_.accepted_terms.begin(), state_.accepted_terms.end(), m.id) != state_.accepted_terms.end();
    name->setCheckState(on ? Qt::Checked : Qt::Unchecked);
    name->setData(Qt::UserRole, q(m.id));
    QString tip = readableModelMessage(m.where);
    if (!m.confused_with.empty()) {
      QStringList c;
      for (const auto& x : m.confused_with) c << termLabel(x);
      tip += "\n" + tr("This log cannot tell it from: %1").arg(c.join(", "));
    }
    for (const auto& rv : m.rivals)
      tip += "\n" + tr("In %1 % of the resampled fits the log chose %2 instead; the answer's uncertainty includes that.")
                         .arg(qRound(100 * rv.inclusion_probability))
                         .arg(termLabel(rv.id));
    if (!m.evidence.empty()) tip += "\n" + q(m.evidence);
    name->setToolTip(tip);
    terms_->setItem(r, 0, name);
    terms_->setItem(r, 1, new QTableWidgetItem(tr("%1 ± %2 %3").arg(sig(m.value, 4), sig(m.sigma, 2), q(m.unit))));
    auto* rms = new QTableWidgetItem(
        tr("%1 → %2 %3").arg(sig(m.rms_before, 3), sig(m.rms_after, 3), q(discrepancy::channelUnit(m.channel))));
    rms->setToolTip(tr("Held-out simulation RMS of %1, without and with this term (fitted on one half of the "
                       "dives/legs, scored on the other).")
                        .arg(channelLabel(m.channel)));
    terms_->setItem(r, 2, rms);
  }
  terms_->resizeColumnsToContents();
  filling_ = false;
}

void ModelCheckPage::showWhere() {
  const auto& r = *outcome_.result;
  QStringList lines;
  for (const auto& m : r.missing_physics)
    if (!m.where.empty()) lines << tr("<b>%1</b> acts where: %2").arg(termLabel(m.id), readableModelMessage(m.where).toHtmlEscaped());
  lines << tr("<b>Where the ballast-only model misses</b>:");
  // The shown channel's simulation error first, then the rest.
  const int shown = shownChannel();
  std::vector<const discrepancy::Localisation*> loc;
  for (const auto& l : r.localisation) loc.push_back(&l);
  if (shown >= 0) {
    const auto ch = outcome_.overlay.channels[static_cast<std::size_t>(shown)].channel;
    std::stable_partition(loc.begin(), loc.end(), [ch](const discrepancy::Localisation* l) {
      return l->channel == ch && l->source == "simulation error";
    });
  }
  for (const auto* l : loc)
    lines << tr("%1, %2: %3").arg(residualSourceLabel(l->source), channelLabel(l->channel), readableModelMessage(l->summary).toHtmlEscaped());
  for (const auto& i : r.identifiability) lines << tr("Cannot be told apart: %1").arg(readableModelText(i.message).toHtmlEscaped());
  for (const auto& w : r.warnings) lines << QStringLiteral("⚠ %1").arg(readableModelText(w).toHtmlEscaped());
  for (const auto& n : r.notes) lines << QStringLiteral("<span style='color:#555'>%1</span>").arg(readableModelText(n).toHtmlEscaped());
  where_->setText(lines.join("<br>"));
}

void ModelCheckPage::updateAccepted() {
  std::vector<std::string> ids;
  for (int r = 0; r < terms_->rowCount(); ++r) {
    const QTableWidgetItem* item = terms_->item(r, 0);
    if (item && (item->flags() & Qt::ItemIsUserCheckable) && item->checkState() == Qt::Checked)
      ids.push_back(item->data(Qt::UserRole).toString().toStdString());
  }
  state_.accepted_terms = ids;
  decided_for_ = outcome_.log;
  if (outcome_.ok && outcome_.result) showSummary();  // the estimate follows the ticks
}

VehicleProfile ModelCheckPage::configurationVehicle() const {
  const VehicleProfile catalog = VehicleCatalog(state_.vehicles_dir).load(state_.vehicle->id);
  if (state_.history_model.is_null()) return catalog;
  return discrepancy::vehicleFromStoredProfile(state_.history_model, catalog, "history: " + state_.configuration_id);
}

bool ModelCheckPage::adoptAcceptedTerms() {
  // The accepted terms become the configuration's vehicle model for the rest
  // of the session (the plan's buoyancy at other depths and temperatures) and
  // are saved with the mission. Always from the model the configuration had,
  // so going back and forth never applies a term twice.
  if (!state_.vehicle || !state_.model_check) return true;
  try {
    const bool from_history = !state_.history_model.is_null();
    const VehicleProfile base = configurationVehicle();
    const VehicleProfile catalog = VehicleCatalog(state_.vehicles_dir).load(state_.vehicle->id);
    if (state_.accepted_terms.empty()) {
      state_.vehicle = base;
      state_.model_profile = state_.history_model;
      return true;
    }
    const nlohmann::json doc = from_history ? state_.history_model : JsonReader::parseFile(catalog.file);
    const std::string log = std::filesystem::path(state_.log_file).filename().string();
    state_.vehicle = discrepancy::vehicleWithAcceptedTerms(doc, base, *state_.model_check, state_.accepted_terms, log,
                                                           &state_.model_profile);
    return true;
  } catch (const InputError& e) {
    save_status_->setText(tr("The accepted terms could not be added to the vehicle model: %1").arg(q(e.what())));
    return false;
  }
}

void ModelCheckPage::setTermAccepted(const std::string& id, bool accepted) {
  for (int r = 0; r < terms_->rowCount(); ++r) {
    QTableWidgetItem* item = terms_->item(r, 0);
    if (item && item->data(Qt::UserRole).toString().toStdString() == id)
      item->setCheckState(accepted ? Qt::Checked : Qt::Unchecked);  // itemChanged -> updateAccepted
  }
}

bool ModelCheckPage::validatePage() {
  // A session resumed past this page may press Next before the check ends.
  if (job_.running()) job_.waitForFinished();
  if (!adoptAcceptedTerms()) return false;
  if (nextId() != -1) return true;
  // Last page of the post-mission sequence: Finish saves the mission.
  auto* wiz = qobject_cast<OperatorWizard*>(wizard());
  HistoryStore* store = wiz ? wiz->history() : nullptr;
  if (!store) return wiz->confirmCloseWithoutHistory();
  try {
    saveMissionToHistory(*store, state_, wiz->now());
  } catch (const InputError& e) {
    save_status_->setText(tr("Not saved: %1").arg(q(e.what())));
    return false;
  }
  wiz->reportSaved(tr("Saved configuration %1: the mission log and its analysis.").arg(q(state_.configuration_id)));
  return true;
}

}  // namespace auv::ui
