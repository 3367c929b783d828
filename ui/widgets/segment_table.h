#pragma once
// The table of the steady segments the analysis used, beside the deviation
// charts: time in minutes and each segment's own errors (an AUV) or means (a
// glider, which has no depth or pitch command to err from). A row click asks
// the charts to zoom to that segment. The strings keep the deviation plots
// page's translation context, where their nb translations are.
#include <QCoreApplication>
#include <optional>
#include <utility>
#include <vector>

#include "analysis/analysis_report.h"

class QTableWidget;

namespace auv::ui {

class SegmentTable {
  Q_DECLARE_TR_FUNCTIONS(auv::ui::DeviationPlotsPage)

 public:
  // Creates the (unparented) table, object name "segments".
  SegmentTable();
  QTableWidget* widget() const { return table_; }

  // One row per used segment of `report` (none when null).
  void show(const analysis::AnalysisReport* report, bool glider);
  // The listed segments' time ranges [min], in row order.
  const std::vector<std::pair<double, double>>& ranges() const { return ranges_; }
  // The time window [min] that shows row `row` with some room either side.
  std::optional<std::pair<double, double>> zoomWindow(int row) const;

 private:
  QTableWidget* table_;
  std::vector<std::pair<double, double>> ranges_;
};

}  // namespace auv::ui
