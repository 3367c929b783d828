#pragma once
#include <QWizardPage>
#include <array>
#include <optional>
#include <vector>

#include "analysis/mission_analysis.h"
#include "common/message.h"
#include "plot/plot_trace.h"
#include "widgets/analysis_summary.h"
#include "widgets/segment_table.h"
#include "wizard/background_task.h"
#include "wizard/wizard_state.h"

class QLabel;
class QPushButton;
QT_BEGIN_NAMESPACE
class QChart;
class QLineSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace auv::ui {

class BusyIndicator;
class LinkedChartView;

// Post mission, step 2: the analysis of the imported log (core/analysis:
// net buoyancy and CG offset with their sigmas, depth/pitch/roll errors with
// 95 % intervals, the water at operating depth, warnings) above depth, pitch
// and roll as flown, each against its command where the log has one. The
// analysis's operating segments are shaded on all three charts and listed
// with their own errors. The charts share the time axis: zoom or pan one and
// the others follow; a crosshair reads time and values across all three.
// Each series holds at most two points per pixel column over the visible
// range (plot/envelope_decimation.h), drawn as a min/max band with the mean
// where the columns are dense, so a 1100 h log stays fluid and readable. The
// analysis and the plot preparation run in worker threads (a busy indicator
// says which; Next waits for them). The charts export as PNG and the
// visible time window as CSV (every sample).
class DeviationPlotsPage : public QWizardPage {
  Q_OBJECT
 public:
  enum Plot { kDepth = 0, kPitch, kRoll };
  explicit DeviationPlotsPage(WizardState& state);
  void initializePage() override;
  bool isComplete() const override;
  bool validatePage() override;

 protected:
  void showEvent(QShowEvent* e) override;

 public:
  int nextId() const override;

  // The analysis or the plot preparation is running in a worker.
  bool busy() const;
  const BusyIndicator& busyIndicator() const { return *busy_; }
  // Applies the workers' results now (waiting for them).
  void finishWork();

  // Visible time range in minutes since the log start, applied to all charts.
  void setXRange(double x0_min, double x1_min);
  void resetXRange();
  std::pair<double, double> xRange(int plot) const;
  std::pair<double, double> fullRange() const { return {t_min_, t_max_}; }
  LinkedChartView* view(int plot) const { return plots_[static_cast<std::size_t>(plot)].view; }
  // Points handed to Qt for series `s` (0 = measured, 1 = commanded) of a plot.
  int pointsDrawn(int plot, int s) const;
  // Samples of that series in the log.
  std::size_t samples(int plot, int s) const;
  // The series' envelope (dense columns): its lower or upper edge, each
  // column's min or max; empty while the series is drawn as a line.
  const QList<QPointF>& bandEdge(int plot, int s, bool upper) const;
  // The series' line: the samples, or the column means inside the band.
  const QLineSeries* line(int plot, int s) const;
  // Operating segments shaded on a chart.
  int shadedSegments(int plot) const;

  // The crosshair at `x_min` on all three charts (nullopt hides it), as the
  // mouse does; the readout under the charts says time and values there.
  void setCrosshair(std::optional<double> x_min);
  QString readoutText() const;

  // The three charts as one PNG; the plotted channels within the visible
  // time window, every logged sample, as a mission-log CSV. Both return
  // false (and say why under the charts) when the file cannot be written;
  // exportCsv returns the number of rows written, -1 on failure.
  bool exportPng(const QString& path);
  long exportCsv(const QString& path);
  // The analysis error when the log could not be analysed (empty otherwise).
  QString analysisError() const { return analysis_error_; }

 private:
  struct Trace {
    PlotTrace data;
    QLineSeries* series = nullptr;  // the samples, or the column means inside the band
  };
  struct PlotData {
    QChart* chart = nullptr;
    LinkedChartView* view = nullptr;
    QValueAxis* x = nullptr;
    QValueAxis* y = nullptr;
    std::array<Trace, 2> traces;
    QString title;
    int buckets = 0;  // plot width the series were decimated for
  };
  void startWork();
  // The history's calibration experiment into o (o.history); the warning
  // when the history could not be read.
  std::optional<Message> addHistoryCalibration(analysis::AnalysisOptions& o) const;
  void showTraces(std::array<std::array<PlotTrace, 2>, 3> traces);
  void showTrace(PlotData& p, std::size_t s, std::size_t buckets, double& lo, double& hi);
  void redecimate();
  void alignPlotAreas();
  void showAnalysis();
  void showSegments();
  void exportPngDialog();
  void exportCsvDialog();
  WizardState& state_;
  std::array<PlotData, 3> plots_;
  double t_min_ = 0.0, t_max_ = 1.0;
  double x0_ = 0.0, x1_ = 1.0;
  std::optional<double> cross_;
  QString analysis_error_;
  AnalysisSummary summary_;
  SegmentTable segments_;  // the operating segments, shaded on the charts
  QWidget* charts_;
  QLabel* info_;
  QLabel* readout_;
  QLabel* status_;
  QPushButton* reset_;
  QPushButton* export_png_;
  QPushButton* export_csv_;
  BusyIndicator* busy_;
  BackgroundTask analysis_task_;
  BackgroundTask plots_task_;
};

}  // namespace auv::ui
