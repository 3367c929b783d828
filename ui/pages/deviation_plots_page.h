#pragma once
#include <QWizardPage>
#include <array>
#include <vector>

#include "wizard/wizard_state.h"

class QLabel;
class QPushButton;
QT_BEGIN_NAMESPACE
class QChart;
class QLineSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace auv::ui {

class LinkedChartView;

// Post mission, step 2: depth, pitch and roll as flown, each against its
// command where the log has one. The three charts share the time axis: zoom
// or pan one and the others follow. Each series holds at most two points per
// pixel column over the visible range (plot/min_max_decimation.h), so a 24 h
// 10 Hz log stays fluid. Finish saves the mission to the history.
class DeviationPlotsPage : public QWizardPage {
  Q_OBJECT
 public:
  enum Plot { kDepth = 0, kPitch, kRoll };
  explicit DeviationPlotsPage(WizardState& state);
  void initializePage() override;
  bool validatePage() override;
  int nextId() const override { return -1; }

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

 private:
  struct Trace {
    std::vector<double> t_min;  // minutes
    std::vector<double> v;
    QLineSeries* series = nullptr;
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
  void buildPlot(PlotData& p, const char* measured, const char* commanded);
  void redecimate();
  void alignPlotAreas();
  WizardState& state_;
  std::array<PlotData, 3> plots_;
  double t_min_ = 0.0, t_max_ = 1.0;
  double x0_ = 0.0, x1_ = 1.0;
  QLabel* info_;
  QLabel* save_status_;
  QPushButton* reset_;
};

}  // namespace auv::ui
