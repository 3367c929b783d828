#pragma once
#include <QtCharts/QChartView>
#include <array>
#include <optional>
#include <vector>

class QGraphicsLineItem;
class QGraphicsRectItem;
class QGraphicsSimpleTextItem;

namespace auv::ui {

// A chart view that does not change its own X axis: wheel (zoom about the
// cursor), drag (pan), +/- and arrow keys, and double-click / Home (reset)
// are turned into a requested X range, which the page applies to every
// linked chart at once and then re-decimates. Moving the mouse reports the X
// value under it (hovered), so the page can draw one crosshair across all
// linked charts. Shaded X bands (e.g. the analysis's operating segments)
// and the crosshair are scene items kept in place on every axis or plot-area
// change.
class LinkedChartView : public QChartView {
  Q_OBJECT
 public:
  explicit LinkedChartView(QChart* chart, QWidget* parent = nullptr);

  // Zoom by `factor` (< 1 = in) about the X value `centre`.
  void zoomX(double factor, double centre);
  void panX(double fraction);  // of the visible width; + = later

  // Shaded X intervals behind the curves; `numbered` draws 1, 2, ... on each.
  void setBands(const std::vector<std::pair<double, double>>& bands, bool numbered);
  int bandCount() const { return static_cast<int>(bands_.size()); }
  // Bands at least partly inside the visible X range.
  int visibleBandCount() const;
  // A min/max envelope behind the lines (slot 0, 1: measured, commanded):
  // a bar per column from `lower[k]` to `upper[k]` (chart values), painted
  // by one item; empty lists hide it. Cheap at any length (the Qt Charts
  // area series took ~0.1 s per repaint).
  void setEnvelope(int slot, QList<QPointF> lower, QList<QPointF> upper, const QColor& color);
  const QList<QPointF>& envelopeEdge(int slot, bool upper) const;
  // A vertical line at X (nullopt hides it).
  void setCrosshair(std::optional<double> x);
  std::optional<double> crosshair() const { return crosshair_x_; }

 signals:
  void xRangeRequested(double x0, double x1);
  void resetRequested();
  void hovered(double x);  // X value under the mouse, inside the plot area
  void hoverLeft();

 protected:
  void wheelEvent(QWheelEvent* e) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void mouseDoubleClickEvent(QMouseEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;
  void leaveEvent(QEvent* e) override;

 private:
  std::pair<double, double> xRange() const;
  double xToPixel(double x) const;
  void layoutOverlays();
  // The bands are painted by one item, and number labels exist only for the
  // bands wide enough to show one: an 1100 h log has thousands of segments,
  // and an item each made every zoom step and the first paint cost ~0.5 s.
  class BandsItem;
  class EnvelopeItem;
  std::array<EnvelopeItem*, 2> envelopes_{};
  std::vector<std::pair<double, double>> bands_;
  bool numbered_ = false;
  BandsItem* bands_item_ = nullptr;
  std::vector<QGraphicsSimpleTextItem*> labels_;  // reused; hidden when unused
  QGraphicsLineItem* crosshair_ = nullptr;
  std::optional<double> crosshair_x_;
  bool dragging_ = false;
  double drag_x_px_ = 0.0;
  std::pair<double, double> drag_range_;
};

}  // namespace auv::ui
