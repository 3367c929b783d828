#include "pages/deviation_plots_page.h"

#include <QFileInfo>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <cmath>

#include "analysis/analysis_messages.h"
#include "analysis/mission_analysis.h"
#include "common/input_error.h"
#include "plot/envelope_decimation.h"
#include "plot/nice_axis.h"
#include "plot/plotted_window_csv.h"
#include "widgets/busy_indicator.h"
#include "widgets/estimate_text.h"
#include "widgets/export_file_dialog.h"
#include "widgets/inputs.h"
#include "widgets/linked_chart_view.h"
#include "wizard/operator_wizard.h"
#include "wizard/pre_mission_inputs.h"
#include "workflow/history_calibration.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

// The sample nearest to x (t ascending), or NaN.
double nearest(const std::vector<double>& t, const std::vector<double>& v, double x) {
  if (t.empty()) return NAN;
  const auto it = std::lower_bound(t.begin(), t.end(), x);
  std::size_t i = static_cast<std::size_t>(it - t.begin());
  if (i == t.size() || (i > 0 && x - t[i - 1] < t[i] - x)) --i;
  return v[i];
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

DeviationPlotsPage::DeviationPlotsPage(WizardState& state) : state_(state) {
  setTitle(tr("Analysis: depth, pitch and roll as flown"));
  setSubTitle(tr("Shaded: the steady segments the analysis used. Wheel or +/-: zoom; drag or arrows: move; "
                 "double-click: whole log."));
  const QString titles[3] = {tr("Depth [m]"), tr("Pitch [°]"), tr("Roll [°]")};
  const char* names[3] = {"chart_depth", "chart_pitch", "chart_roll"};
  charts_ = new QWidget;
  charts_->setObjectName("charts");
  auto* clay = new QVBoxLayout(charts_);
  clay->setContentsMargins(0, 0, 0, 0);
  clay->setSpacing(2);
  for (std::size_t i = 0; i < 3; ++i) {
    PlotData& p = plots_[i];
    p.title = titles[i];
    p.chart = new QChart;
    p.chart->setAnimationOptions(QChart::NoAnimation);
    // One legend (on the depth chart) explains the colours of all three,
    // leaving the height to the curves.
    p.chart->legend()->setAlignment(Qt::AlignTop);
    p.chart->legend()->setVisible(i == kDepth);
    p.chart->setBackgroundRoundness(0);
    p.chart->layout()->setContentsMargins(0, 0, 0, 0);
    p.chart->setMargins(QMargins(4, 2, 4, 2));
    // "not in this log: ..." needs little room: the height is for the curves.
    QFont small = p.chart->titleFont();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    p.chart->setTitleFont(small);
    p.x = new QValueAxis;
    p.x->setLabelFormat("%.0f");
    p.x->setTickType(QValueAxis::TicksDynamic);
    p.x->setTickAnchor(0.0);
    p.y = new QValueAxis;
    p.y->setLabelFormat("%.1f");
    p.y->setTitleText(titles[i]);
    p.chart->addAxis(p.x, Qt::AlignBottom);
    p.chart->addAxis(p.y, Qt::AlignLeft);
    for (std::size_t s = 0; s < 2; ++s) {
      auto* series = new QLineSeries;
      series->setName(s == 0 ? tr("measured") : tr("commanded"));
      // Solid pens: a dashed pen over thousands of segments is the most
      // expensive thing Qt can be asked to stroke.
      QPen pen(s == 0 ? QColor(31, 119, 180) : QColor(230, 120, 20));
      pen.setWidth(s == 0 ? 1 : 2);
      series->setPen(pen);
      // Series are filled with replace() after attaching: at most ~2 points
      // per pixel, so the O(n) attach cost of a huge series never occurs.
      p.chart->addSeries(series);
      series->attachAxis(p.x);
      series->attachAxis(p.y);
      p.traces[s].series = series;
    }
    if (i == kDepth) p.y->setReverse(true);  // depth positive down, drawn down
    if (i == kRoll) p.x->setTitleText(tr("time since start [min]"));
    p.view = new LinkedChartView(p.chart);
    p.view->setObjectName(names[i]);
    p.view->setMinimumHeight(120);
    clay->addWidget(p.view, 1);
    connect(p.view, &LinkedChartView::xRangeRequested, this, [this](double a, double b) { setXRange(a, b); });
    connect(p.view, &LinkedChartView::resetRequested, this, [this] { resetXRange(); });
    connect(p.view, &LinkedChartView::hovered, this, [this](double x) { setCrosshair(x); });
    connect(p.view, &LinkedChartView::hoverLeft, this, [this] { setCrosshair(std::nullopt); });
    // A resize changes the pixel columns: decimate again for the new width.
    connect(p.chart, &QChart::plotAreaChanged, this, [this, i](const QRectF& r) {
      if (std::abs(static_cast<int>(r.width()) - plots_[i].buckets) > 2) redecimate();
    });
  }

  QTableWidget* segment_table = segments_.widget();
  auto* scroll = new QScrollArea;
  scroll->setWidget(summary_.notes());
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  info_ = new QLabel;
  info_->setObjectName("plots_info");
  info_->setWordWrap(true);
  info_->setStyleSheet("color: #555;");
  auto* side = new QWidget;
  side->setFixedWidth(380);
  auto* slay = new QVBoxLayout(side);
  slay->setContentsMargins(0, 0, 0, 0);
  auto* seg_title = new QLabel(tr("Steady &segments used"));
  seg_title->setBuddy(segment_table);
  slay->addWidget(seg_title);
  slay->addWidget(segment_table, 1);
  slay->addWidget(scroll, 1);
  slay->addWidget(info_);

  readout_ = new QLabel;
  readout_->setObjectName("crosshair_readout");
  readout_->setWordWrap(true);
  reset_ = button(tr("&Whole log"), "reset_zoom", tr("Show the whole log in all three charts."));
  export_png_ = button(tr("Export &PNG…"), "export_png", tr("Save the three charts as they are shown as a PNG image."));
  export_csv_ = button(tr("Export &CSV…"), "export_csv",
                       tr("Save every logged sample of the plotted channels within the visible time window "
                          "as a mission-log CSV (not the thinned-out points drawn)."));
  status_ = makeErrorLabel("export_status");
  busy_ = new BusyIndicator;
  busy_->follow(&plots_task_);  // first: the pool prepares the plots first
  busy_->follow(&analysis_task_);
  connect(busy_, &BusyIndicator::busyChanged, this, [this] { emit completeChanged(); });

  auto* body = new QHBoxLayout;
  body->addWidget(charts_, 1);
  body->addWidget(side);
  auto* row = new QHBoxLayout;
  row->addWidget(readout_, 1);
  row->addWidget(reset_);
  row->addWidget(export_png_);
  row->addWidget(export_csv_);
  auto* lay = new QVBoxLayout(this);
  lay->setSpacing(4);
  lay->addWidget(busy_);
  lay->addLayout(summary_.grid());
  lay->addLayout(body, 1);
  lay->addLayout(row);
  lay->addWidget(status_);
  setTabOrder(plots_[kDepth].view, plots_[kPitch].view);
  setTabOrder(plots_[kPitch].view, plots_[kRoll].view);
  setTabOrder(plots_[kRoll].view, segment_table);
  setTabOrder(segment_table, reset_);
  setTabOrder(reset_, export_png_);
  setTabOrder(export_png_, export_csv_);
  connect(reset_, &QPushButton::clicked, this, [this] { resetXRange(); });
  connect(export_png_, &QPushButton::clicked, this, [this] { exportPngDialog(); });
  connect(export_csv_, &QPushButton::clicked, this, [this] { exportCsvDialog(); });
  connect(segment_table, &QTableWidget::cellClicked, this, [this](int r, int) {
    if (const auto w = segments_.zoomWindow(r)) setXRange(w->first, w->second);
  });
}

void DeviationPlotsPage::showEvent(QShowEvent* e) {
  // Back from the model-check page: the estimate the plan uses may have
  // changed with the terms accepted there (QWizard does not initialise a
  // page again on Back).
  if (state_.log) showAnalysis();
  QWizardPage::showEvent(e);
}

int DeviationPlotsPage::nextId() const { return OperatorWizard::kModelCheck; }

bool DeviationPlotsPage::busy() const { return busy_->busy(); }

bool DeviationPlotsPage::isComplete() const { return !busy(); }

void DeviationPlotsPage::finishWork() {
  analysis_task_.finishNow();
  plots_task_.finishNow();
}

bool DeviationPlotsPage::validatePage() {
  // A resumed session or a test may press Next before the workers end.
  finishWork();
  return true;
}

void DeviationPlotsPage::initializePage() {
  status_->clear();
  if (!state_.log) return;
  startWork();
}

namespace {
// The measured and commanded channel of each chart.
constexpr const char* kChannels[3][2] = {{"depth", "depth_cmd"}, {"pitch", "pitch_cmd"}, {"roll", nullptr}};

// A channel the log lacks, in the words of the page (no channel ids).
QString channelWords(const char* name) {
  const QString n = QString::fromLatin1(name);
  if (n == "depth_cmd") return DeviationPlotsPage::tr("commanded depth");
  if (n == "pitch_cmd") return DeviationPlotsPage::tr("commanded pitch");
  return DeviationPlotsPage::tr(name);
}
}  // namespace

std::optional<Message> DeviationPlotsPage::addHistoryCalibration(analysis::AnalysisOptions& o) const {
  // A configuration from the history: its latest analysed mission and the
  // known weight change since calibrate with this log (as model-check
  // --config does). Read here, on the wizard's thread, which owns the store.
  auto* w = qobject_cast<OperatorWizard*>(wizard());
  HistoryStore* store = w ? w->history() : nullptr;
  if (!store || state_.isGlider() || !state_.configuration_in_history || o.installed_kg.empty()) return std::nullopt;
  try {
    o.history = historyCalibrationMissions(*store, state_.configuration_id, *state_.vehicle, w->now(), o.log_name);
  } catch (const std::exception& e) {  // a damaged row costs the calibration, not the analysis
    return Message(analysis::msg::kHistoryUnreadable, {state_.configuration_id, e.what()});
  }
  return std::nullopt;
}

void DeviationPlotsPage::startWork() {
  const std::shared_ptr<const MissionLog> log = state_.log;
  // The plots first (quick), so the technician sees the log while the
  // analysis runs; each result is dropped if another log came meanwhile.
  plots_task_.start(tr("Preparing the plots of %1 rows…").arg(log->rowCount()), [this, log]() -> BackgroundTask::Apply {
    auto traces = std::make_shared<std::array<std::array<PlotTrace, 2>, 3>>();
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t k = 0; k < 2; ++k) (*traces)[i][k] = preparePlotTrace(*log, kChannels[i][k]);
    return [this, log, traces] {
      if (state_.log == log) showTraces(std::move(*traces));
    };
  });
  analysis_error_.clear();
  if (state_.analysis) {
    BackgroundTask::settle({&plots_task_});
    showAnalysis();
    showSegments();
    return;
  }
  summary_.showPending(tr("Net buoyancy: being computed…"));
  segments_.show(nullptr, state_.isGlider());
  if (!state_.vehicle) {
    BackgroundTask::settle({&plots_task_});
    analysis_error_ = q(InputError("vehicle", "no vehicle chosen", "go back to the vehicle page").what());
    showAnalysis();
    return;
  }
  analysis::AnalysisOptions o;
  o.log_name = QFileInfo(q(state_.log_file)).fileName().toStdString();
  // The import page entered one value per point (AUVs); a glider's fit has no use for it.
  if (!state_.isGlider() && state_.mission_installed_kg.size() == state_.vehicle->points.size())
    o.installed_kg = state_.mission_installed_kg;
  // BG from the configuration (roll test): CG y and roll become identifiable.
  if (state_.bg_mm && !state_.isGlider()) o.bg_m = *state_.bg_mm / 1000.0;
  // A level check of the pitch sensor narrows the prior on its bias.
  if (state_.pitch_alignment_sigma_deg) o.pitch_alignment_sigma_deg = *state_.pitch_alignment_sigma_deg;
  const std::optional<Message> history_problem = addHistoryCalibration(o);
  analysis_task_.start(
      tr("Analysing the log: steady segments, depth, pitch and roll errors, net buoyancy and centre of gravity…"),
      [this, log, vehicle = *state_.vehicle, o, history_problem]() -> BackgroundTask::Apply {
        auto result = std::make_shared<std::optional<analysis::AnalysisReport>>();
        QString error;
        try {
          *result = analysis::analyzeMission(*log, vehicle, o);
          if (history_problem) (*result)->warnings.insert((*result)->warnings.begin(), *history_problem);
        } catch (const std::exception& e) {
          error = q(e.what());
        }
        return [this, log, result, error] {
          if (state_.log != log) return;
          analysis_error_ = error;
          if (*result) state_.analysis = std::move(**result);
          showAnalysis();
          showSegments();
        };
      });
  BackgroundTask::settle({&plots_task_, &analysis_task_});
}

void DeviationPlotsPage::showTraces(std::array<std::array<PlotTrace, 2>, 3> traces) {
  bool any_command = false;
  std::size_t n = 0;
  for (std::size_t i = 0; i < plots_.size(); ++i) {
    PlotData& p = plots_[i];
    QStringList missing;
    for (std::size_t s = 0; s < 2; ++s) {
      Trace& t = p.traces[s];
      t.data = std::move(traces[i][s]);
      n += t.data.v.size();
      t.series->setVisible(t.data.channel != nullptr);
      if (!t.data.channel && kChannels[i][s]) missing << channelWords(kChannels[i][s]);
    }
    p.traces[1].series->setName(kChannels[i][1] ? tr("commanded") : QString());
    for (QLegendMarker* m : p.chart->legend()->markers(p.traces[1].series)) m->setVisible(p.traces[1].series->isVisible());
    p.chart->setTitle(missing.isEmpty() ? QString() : tr("not in this log: %1").arg(missing.join(", ")));
    any_command = any_command || p.traces[1].series->isVisible();
  }
  // The legend only tells measured from commanded: without any command it
  // would take a line of the depth chart to name one colour.
  plots_[kDepth].chart->legend()->setVisible(any_command);
  const MissionLog& log = *state_.log;
  t_min_ = log.time.empty() ? 0.0 : log.time.front() / 60.0;
  t_max_ = log.time.empty() ? 1.0 : log.time.back() / 60.0;
  if (t_max_ <= t_min_) t_max_ = t_min_ + 1.0;
  info_->setText(tr("%1: %2 samples in the three charts over %3 min.")
                     .arg(QString::fromStdString(state_.log_file).section('/', -1))
                     .arg(n)
                     .arg(fixed(t_max_ - t_min_, 0)));
  cross_.reset();
  setCrosshair(std::nullopt);
  resetXRange();
}

void DeviationPlotsPage::showAnalysis() {
  // The estimate the plan uses: with accepted model-check terms (after Back
  // from the model-check page) it is the check's ballast state.
  const auto e = sessionEstimate(state_);
  QString source;
  if (e && !e->report.net_buoyancy_kg.known && !state_.isGlider()) {
    source = tr("The next page's model check fits the whole log, which may tell the net buoyancy where the steady "
                "flight cannot.");
  } else if (e) {
    source = EstimateText::planUses(e->source);
    if (e->source == discrepancy::EstimateSource::kModelCheck || e->source == discrepancy::EstimateSource::kModelCheckReplay)
      source += " " + tr("This log's analysis alone: net buoyancy %1.")
                          .arg(EstimateText::of(state_.analysis->net_buoyancy_kg, state_.isGlider() ? 3 : 2, tr(" kg")));
  }
  summary_.show(e ? &e->report : nullptr, state_.isGlider(), analysis_error_, source);
}

void DeviationPlotsPage::showSegments() {
  segments_.show(state_.analysis ? &*state_.analysis : nullptr, state_.isGlider());
  for (std::size_t i = 0; i < plots_.size(); ++i) plots_[i].view->setBands(segments_.ranges(), i == kDepth);
}

int DeviationPlotsPage::shadedSegments(int plot) const { return view(plot)->bandCount(); }

void DeviationPlotsPage::setCrosshair(std::optional<double> x) {
  cross_ = x;
  for (auto& p : plots_) p.view->setCrosshair(x);
  if (!x || !state_.log) {
    readout_->setText(tr("Point at a chart to read the time and the values there."));
    return;
  }
  const auto value = [&](int plot, int s, const QString& unit) -> QString {
    const Trace& t = plots_[static_cast<std::size_t>(plot)].traces[static_cast<std::size_t>(s)];
    const double v = nearest(t.data.t_min, t.data.v, *x);
    return std::isfinite(v) ? fixed(v, 2) + unit : QString();
  };
  QStringList parts;
  const char* names[3] = {QT_TR_NOOP("depth"), QT_TR_NOOP("pitch"), QT_TR_NOOP("roll")};
  const QString units[3] = {tr(" m"), tr("°"), tr("°")};
  for (int plot = kDepth; plot <= kRoll; ++plot) {
    const QString m = value(plot, 0, units[plot]), c = value(plot, 1, units[plot]);
    if (m.isEmpty() && c.isEmpty()) continue;
    parts << (c.isEmpty() ? tr("%1 %2").arg(tr(names[plot]), m) : tr("%1 %2 (command %3)").arg(tr(names[plot]), m, c));
  }
  readout_->setText(tr("<b>%1 min</b>: %2").arg(fixed(*x, 2), parts.join(", ")));
}

QString DeviationPlotsPage::readoutText() const { return readout_->text(); }

void DeviationPlotsPage::resetXRange() { setXRange(t_min_, t_max_); }

void DeviationPlotsPage::setXRange(double x0, double x1) {
  if (!(x1 > x0)) return;
  const double full = t_max_ - t_min_;
  const double min_width = std::max(full * 1e-6, 1e-4);  // ~ a few samples
  double w = std::clamp(x1 - x0, min_width, full);
  x0 = std::clamp(x0, t_min_, t_max_ - w);
  x0_ = x0;
  x1_ = x0 + w;
  // Round time ticks (1, 2, 5 x 10^k minutes) whatever the zoom.
  const NiceAxis ticks = niceAxis(x0_, x1_, 6);
  const int decimals = ticks.step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(ticks.step)));
  for (auto& p : plots_) {
    p.x->setRange(x0_, x1_);
    p.x->setTickInterval(ticks.step);
    p.x->setLabelFormat(QString("%.%1f").arg(decimals));
  }
  redecimate();
}

std::pair<double, double> DeviationPlotsPage::xRange(int plot) const {
  const auto* x = plots_[static_cast<std::size_t>(plot)].x;
  return {x->min(), x->max()};
}

void DeviationPlotsPage::showTrace(PlotData& p, std::size_t s, std::size_t buckets, double& lo, double& hi) {
  Trace& t = p.traces[s];
  const Envelope e = decimateEnvelope(t.data.t_min, t.data.v, t.data.pyramid, x0_, x1_, buckets);
  const auto toList = [&](const std::vector<PlotPoint>& pts) {
    QList<QPointF> list;
    list.reserve(static_cast<qsizetype>(pts.size()));
    for (const auto& pt : pts) {
      list.append(QPointF(pt.x, pt.y));
      if (pt.x >= x0_ && pt.x <= x1_) {
        lo = std::min(lo, pt.y);
        hi = std::max(hi, pt.y);
      }
    }
    return list;
  };
  t.series->replace(toList(e.line));
  // The band in the line's colour, light: the level (mean line) stays readable on it.
  QColor band = t.series->pen().color();
  band.setAlpha(s == 0 ? 70 : 60);
  p.view->setEnvelope(static_cast<int>(s), toList(e.lower), toList(e.upper), band);
}

void DeviationPlotsPage::redecimate() {
  for (auto& p : plots_) {
    const int width = static_cast<int>(p.chart->plotArea().width());
    const std::size_t buckets = static_cast<std::size_t>(std::max(width, 200));
    p.buckets = width;
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t s = 0; s < p.traces.size(); ++s) showTrace(p, s, buckets, lo, hi);
    // Y follows what is visible, on round ticks.
    if (std::isfinite(lo) && std::isfinite(hi)) {
      // Surface noise just above 0 m must not add a whole tick of air.
      if (&p == &plots_[kDepth] && lo < 0.0 && lo > -0.05 * (hi - lo)) lo = 0.0;
      // Three intervals: the charts are short and labels must not touch
      // (a count from the plot height would feed back into the layout).
      const NiceAxis a = niceAxis(lo, hi, 3);
      // As many decimals as the tick step needs: "200", "50.2", "0.05" (set
      // before the range, so the axis is laid out for the new labels).
      const int d = a.step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(a.step) - 1e-9));
      const QString format = QString("%.%1f").arg(d);
      if (p.y->labelFormat() != format) p.y->setLabelFormat(format);
      if (a.min != p.y->min() || a.max != p.y->max()) p.y->setRange(a.min, a.max);
      p.y->setTickCount(a.ticks);
    }
  }
  alignPlotAreas();
}

void DeviationPlotsPage::alignPlotAreas() {
  // Linked time axes must line up: pad each chart's left margin by the
  // difference between the widest Y labels of all charts and its own.
  std::array<double, 3> label_w{};
  double widest = 0;
  for (std::size_t i = 0; i < plots_.size(); ++i) {
    const QValueAxis* y = plots_[i].y;
    const QFontMetricsF fm(y->labelsFont());
    const int n = std::max(y->tickCount(), 2);
    for (int k = 0; k < n; ++k) {
      const double v = y->min() + (y->max() - y->min()) * k / (n - 1);
      label_w[i] = std::max(label_w[i], fm.horizontalAdvance(QString::asprintf(y->labelFormat().toLatin1().constData(), v)));
    }
    widest = std::max(widest, label_w[i]);
  }
  for (std::size_t i = 0; i < plots_.size(); ++i) {
    const int pad = static_cast<int>(std::lround(widest - label_w[i]));
    plots_[i].chart->setMargins(QMargins(4 + pad, 2, 12, 2));
  }
}

int DeviationPlotsPage::pointsDrawn(int plot, int s) const {
  const auto* series = plots_[static_cast<std::size_t>(plot)].traces[static_cast<std::size_t>(s)].series;
  return series->isVisible() ? static_cast<int>(series->count()) : 0;
}

std::size_t DeviationPlotsPage::samples(int plot, int s) const {
  return plots_[static_cast<std::size_t>(plot)].traces[static_cast<std::size_t>(s)].data.v.size();
}

const QLineSeries* DeviationPlotsPage::line(int plot, int s) const {
  return plots_[static_cast<std::size_t>(plot)].traces[static_cast<std::size_t>(s)].series;
}

const QList<QPointF>& DeviationPlotsPage::bandEdge(int plot, int s, bool upper) const {
  return view(plot)->envelopeEdge(s, upper);
}

bool DeviationPlotsPage::exportPng(const QString& path) {
  status_->clear();
  if (!charts_->grab().save(path, "PNG")) {
    status_->setText(tr("Could not write %1: check the folder and its permissions.").arg(path));
    return false;
  }
  return true;
}

long DeviationPlotsPage::exportCsv(const QString& path) {
  status_->clear();
  if (!state_.log) return -1;
  const MissionLog& log = *state_.log;
  std::vector<const LogChannel*> channels;
  for (const auto& p : plots_)
    for (const auto& t : p.traces)
      if (t.data.channel) channels.push_back(&log.channel(t.data.channel));
  try {
    return writePlottedWindowCsv(log, channels, x0_, x1_, QFileInfo(q(state_.log_file)).fileName(), path);
  } catch (const InputError& e) {
    status_->setText(tr("Not exported: %1").arg(q(e.what())));
    return -1;
  }
}

void DeviationPlotsPage::exportPngDialog() {
  const QString file = askExportFile(this, tr("Export the charts"), state_.log_file, "_plots.png", tr("PNG images (*.png)"));
  if (!file.isEmpty()) exportPng(file);
}

void DeviationPlotsPage::exportCsvDialog() {
  const QString file =
      askExportFile(this, tr("Export the plotted data"), state_.log_file, "_window.csv", tr("CSV files (*.csv)"));
  if (!file.isEmpty()) exportCsv(file);
}

}  // namespace auv::ui
