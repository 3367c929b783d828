#pragma once
#include <QtCharts/QChartView>

namespace auv::ui {

// A chart view that does not change its own X axis: wheel (zoom about the
// cursor), drag (pan), +/- and arrow keys, and double-click / Home (reset)
// are turned into a requested X range, which the page applies to every
// linked chart at once and then re-decimates.
class LinkedChartView : public QChartView {
  Q_OBJECT
 public:
  explicit LinkedChartView(QChart* chart, QWidget* parent = nullptr);

  // Zoom by `factor` (< 1 = in) about the X value `centre`.
  void zoomX(double factor, double centre);
  void panX(double fraction);  // of the visible width; + = later

 signals:
  void xRangeRequested(double x0, double x1);
  void resetRequested();

 protected:
  void wheelEvent(QWheelEvent* e) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void mouseDoubleClickEvent(QMouseEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;

 private:
  std::pair<double, double> xRange() const;
  bool dragging_ = false;
  double drag_x_px_ = 0.0;
  std::pair<double, double> drag_range_;
};

}  // namespace auv::ui
