#include "pages/deviation_plots_page.h"

#include <QHBoxLayout>
#include <QFontMetricsF>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <QGraphicsLayout>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "history/store.h"
#include "plot/min_max_decimation.h"
#include "plot/nice_axis.h"
#include "widgets/inputs.h"
#include "widgets/linked_chart_view.h"
#include "wizard/history_save.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {

DeviationPlotsPage::DeviationPlotsPage(WizardState& state) : state_(state) {
  setTitle(tr("Depth, pitch and roll as flown"));
  setSubTitle(tr("Measured against commanded. Wheel or +/- zooms in time, drag or the arrow keys move, "
                 "double-click shows the whole log; the three charts move together."));
  const QString titles[3] = {tr("Depth [m]"), tr("Pitch [°]"), tr("Roll [°]")};
  const char* names[3] = {"chart_depth", "chart_pitch", "chart_roll"};
  auto* lay = new QVBoxLayout(this);
  lay->setSpacing(2);
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
    p.view->setMinimumHeight(150);
    lay->addWidget(p.view, 1);
    connect(p.view, &LinkedChartView::xRangeRequested, this, [this](double a, double b) { setXRange(a, b); });
    connect(p.view, &LinkedChartView::resetRequested, this, [this] { resetXRange(); });
    // A resize changes the pixel columns: decimate again for the new width.
    connect(p.chart, &QChart::plotAreaChanged, this, [this, i](const QRectF& r) {
      if (std::abs(static_cast<int>(r.width()) - plots_[i].buckets) > 2) redecimate();
    });
  }
  info_ = new QLabel;
  info_->setObjectName("plots_info");
  info_->setWordWrap(true);
  reset_ = new QPushButton(tr("&Whole log"));
  reset_->setObjectName("reset_zoom");
  reset_->setToolTip(tr("Show the whole log in all three charts."));
  reset_->setMinimumHeight(32);
  reset_->setAutoDefault(false);
  save_status_ = makeErrorLabel("save_status");
  auto* row = new QHBoxLayout;
  row->addWidget(info_, 1);
  row->addWidget(reset_);
  lay->addLayout(row);
  lay->addWidget(save_status_);
  connect(reset_, &QPushButton::clicked, this, [this] { resetXRange(); });
}

void DeviationPlotsPage::buildPlot(PlotData& p, const char* measured, const char* commanded) {
  const MissionLog& log = *state_.log;
  const char* names[2] = {measured, commanded};
  QStringList missing;
  for (std::size_t s = 0; s < 2; ++s) {
    Trace& tr = p.traces[s];
    tr.t_min.clear();
    tr.v.clear();
    if (!names[s] || !log.has(names[s])) {
      if (names[s]) missing << names[s];
      tr.series->setVisible(false);
      continue;
    }
    const TimeSeries ts = log.series(names[s]);
    tr.t_min.resize(ts.t.size());
    std::transform(ts.t.begin(), ts.t.end(), tr.t_min.begin(), [](double t) { return t / 60.0; });
    tr.v = ts.v;
    tr.series->setVisible(true);
  }
  p.traces[1].series->setName(commanded ? tr("commanded") : QString());
  if (!commanded) p.traces[1].series->setVisible(false);
  for (QLegendMarker* m : p.chart->legend()->markers(p.traces[1].series)) m->setVisible(p.traces[1].series->isVisible());
  p.chart->setTitle(missing.isEmpty() ? QString() : tr("not in this log: %1").arg(missing.join(", ")));
}

void DeviationPlotsPage::initializePage() {
  save_status_->clear();
  if (!state_.log) return;
  buildPlot(plots_[kDepth], "depth", "depth_cmd");
  buildPlot(plots_[kPitch], "pitch", "pitch_cmd");
  buildPlot(plots_[kRoll], "roll", nullptr);
  const MissionLog& log = *state_.log;
  t_min_ = log.time.empty() ? 0.0 : log.time.front() / 60.0;
  t_max_ = log.time.empty() ? 1.0 : log.time.back() / 60.0;
  if (t_max_ <= t_min_) t_max_ = t_min_ + 1.0;
  std::size_t n = 0;
  for (const auto& p : plots_)
    for (const auto& t : p.traces) n += t.v.size();
  info_->setText(tr("%1: %2 samples in the three charts over %3 min.")
                     .arg(QString::fromStdString(state_.log_file).section('/', -1))
                     .arg(n)
                     .arg(t_max_ - t_min_, 0, 'f', 0));
  resetXRange();
}

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

void DeviationPlotsPage::redecimate() {
  for (auto& p : plots_) {
    const int width = static_cast<int>(p.chart->plotArea().width());
    const std::size_t buckets = static_cast<std::size_t>(std::max(width, 200));
    p.buckets = width;
    double lo = INFINITY, hi = -INFINITY;
    for (auto& tr : p.traces) {
      const auto pts = decimateMinMax(tr.t_min, tr.v, x0_, x1_, buckets);
      QList<QPointF> list;
      list.reserve(static_cast<qsizetype>(pts.size()));
      for (const auto& pt : pts) {
        list.append(QPointF(pt.x, pt.y));
        if (pt.x >= x0_ && pt.x <= x1_) {
          lo = std::min(lo, pt.y);
          hi = std::max(hi, pt.y);
        }
      }
      tr.series->replace(list);
    }
    // Y follows what is visible, on round ticks.
    if (std::isfinite(lo) && std::isfinite(hi)) {
      const NiceAxis a = niceAxis(lo, hi);
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
      label_w[i] = std::max(label_w[i], fm.horizontalAdvance(QString::asprintf("%.1f", v)));
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
  return plots_[static_cast<std::size_t>(plot)].traces[static_cast<std::size_t>(s)].v.size();
}

bool DeviationPlotsPage::validatePage() {
  auto* wiz = qobject_cast<OperatorWizard*>(wizard());
  HistoryStore* store = wiz ? wiz->history() : nullptr;
  if (!store) return true;
  try {
    saveMissionToHistory(*store, state_, wiz->now());
  } catch (const InputError& e) {
    save_status_->setText(tr("Not saved: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
  return true;
}

}  // namespace auv::ui
