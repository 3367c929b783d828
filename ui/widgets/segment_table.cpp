#include "widgets/segment_table.h"

#include "widgets/estimate_text.h"

#include <QHeaderView>
#include <QTableWidget>
#include <algorithm>
#include <cmath>

#include "widgets/inputs.h"

namespace auv::ui {
namespace {

// The cell: mean and its 95 % interval at the column's decimals, the
// interval at least one unit of the last digit (a 0.001 deg interval shows
// as "±0.01", never "±0.00"), so that it fits the narrow side panel; more
// digits were elided to "+2.786 …" and lost the interval. The tooltip has
// the digits.
QString cellText(double mean, double ci, int decimals) {
  if (!std::isfinite(mean)) return QStringLiteral("—");
  if (!std::isfinite(ci)) return signedFixed(mean, decimals);
  const double scale = std::pow(10.0, decimals);
  const double ci_up = std::max(1.0, std::round(ci * scale)) / scale;
  return QStringLiteral("%1 ±%2").arg(signedFixed(mean, decimals), fixed(ci_up, decimals));
}

// The tooltip: as many decimals as the interval needs.
QString preciseText(double mean, double ci, int decimals) {
  if (!std::isfinite(mean)) return {};
  decimals = EstimateText::decimalsFor(ci, decimals);
  return std::isfinite(ci) ? QStringLiteral("%1 ± %2 (95 %)").arg(signedFixed(mean, decimals), fixed(ci, decimals))
                           : signedFixed(mean, decimals);
}

}  // namespace

SegmentTable::SegmentTable() {
  table_ = new QTableWidget(0, 5);
  table_->setObjectName("segments");
  table_->setHorizontalHeaderLabels({tr("#"), tr("min"), tr("Depth [m]"), tr("Pitch [°]"), tr("Roll [°]")});
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(22);
  // No horizontal scrolling: # and the time as wide as they need, the
  // three error columns share the rest.
  for (int c = 0; c < 5; ++c)
    table_->horizontalHeader()->setSectionResizeMode(c, c < 2 ? QHeaderView::ResizeToContents : QHeaderView::Stretch);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
}

void SegmentTable::show(const analysis::AnalysisReport* report, bool glider) {
  ranges_.clear();
  table_->setRowCount(0);
  // A glide has no depth or pitch command to err from: its means instead.
  const bool g = glider;
  table_->setToolTip(
      g ? tr("Each steady glide the analysis used (time in minutes): its mean depth and pitch, and the roll ± its "
             "95 % interval. Click a row to zoom to it.")
        : tr("Each steady segment the analysis used (time in minutes): mean error ± its 95 % interval (depth: "
             "commanded − measured; pitch: measured − commanded; roll: as measured). A dive or climb (the steady "
             "middle of a depth change) shows its mean pitch instead. Click a row to zoom to it."));
  if (!report) return;
  // All rows at once: a row inserted at a time costs ~0.1 s per thousand
  // (an 1100 h log has thousands of segments).
  table_->setRowCount(static_cast<int>(
      std::count_if(report->segments.begin(), report->segments.end(), [](const auto& s) { return s.used; })));
  int r = -1;
  for (const auto& s : report->segments) {
    if (!s.used) continue;
    ++r;
    ranges_.push_back({s.start_s / 60.0, s.end_s / 60.0});
    // An AUV's steady dive or climb (the middle of a depth change) calibrates
    // the lift but has no depth or pitch error: it says so, with its pitch.
    const bool auv_glide = !g && s.kind == analysis::SegmentKind::kGlide;
    const QString cells[5] = {
        QString::number(r + 1), QStringLiteral("%1–%2").arg(fixed(s.start_s / 60.0, 1)).arg(fixed(s.end_s / 60.0, 1)),
        g           ? cellText(s.depth_m, NAN, 1)
        : auv_glide ? (s.calibration_dropped ? tr("left out") : tr("dive/climb"))
                    : cellText(s.depth_error_m, s.depth_error_ci95_m, 2),
        g || auv_glide ? cellText(s.pitch_deg, NAN, 1) : cellText(s.pitch_error_deg, s.pitch_error_ci95_deg, 2),
        cellText(s.roll_deg, s.roll_ci95_deg, 2)};
    const QString tips[5] = {
        {}, {},
        g           ? QString()
        : auv_glide ? (s.calibration_dropped
                           ? tr("A dive or climb left out of the calibration: the other legs' balance does not explain it.")
                           : QString())
                    : preciseText(s.depth_error_m, s.depth_error_ci95_m, 2),
        g || auv_glide ? QString() : preciseText(s.pitch_error_deg, s.pitch_error_ci95_deg, 2),
        preciseText(s.roll_deg, s.roll_ci95_deg, 2)};
    for (int c = 0; c < 5; ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      if (!tips[c].isEmpty()) item->setToolTip(tips[c]);
      item->setTextAlignment(c == 0 ? Qt::AlignCenter : Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(r, c, item);
    }
  }
}

std::optional<std::pair<double, double>> SegmentTable::zoomWindow(int row) const {
  if (row < 0 || row >= static_cast<int>(ranges_.size())) return std::nullopt;
  const auto [a, b] = ranges_[static_cast<std::size_t>(row)];
  const double pad = std::max((b - a) * 0.15, 0.5);
  return std::pair{a - pad, b + pad};
}

}  // namespace auv::ui
