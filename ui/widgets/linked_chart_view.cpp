#include "widgets/linked_chart_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>
#include <QtCharts/QValueAxis>
#include <cmath>

namespace auv::ui {

LinkedChartView::LinkedChartView(QChart* chart, QWidget* parent) : QChartView(chart, parent) {
  setFocusPolicy(Qt::StrongFocus);
  // No anti-aliasing: with ~2 points per pixel column it hardly shows, and
  // it doubles the cost of every repaint of a zoomed or panned chart.
  setRenderHint(QPainter::Antialiasing, false);
  setToolTip(tr("Wheel or +/-: zoom in time. Drag or arrow keys: move in time. Double-click or Home: whole log. "
                "All three charts follow."));
}

std::pair<double, double> LinkedChartView::xRange() const {
  const auto axes = chart()->axes(Qt::Horizontal);
  if (axes.isEmpty()) return {0.0, 1.0};
  const auto* a = qobject_cast<QValueAxis*>(axes.first());
  return a ? std::pair{a->min(), a->max()} : std::pair{0.0, 1.0};
}

void LinkedChartView::zoomX(double factor, double centre) {
  const auto [x0, x1] = xRange();
  emit xRangeRequested(centre - (centre - x0) * factor, centre + (x1 - centre) * factor);
}

void LinkedChartView::panX(double fraction) {
  const auto [x0, x1] = xRange();
  const double d = (x1 - x0) * fraction;
  emit xRangeRequested(x0 + d, x1 + d);
}

void LinkedChartView::wheelEvent(QWheelEvent* e) {
  const double steps = e->angleDelta().y() / 120.0;
  if (steps == 0) return;
  const double centre = chart()->mapToValue(e->position()).x();
  zoomX(std::pow(0.8, steps), centre);
  e->accept();
}

void LinkedChartView::mousePressEvent(QMouseEvent* e) {
  if (e->button() == Qt::LeftButton) {
    dragging_ = true;
    drag_x_px_ = e->position().x();
    drag_range_ = xRange();
    setCursor(Qt::ClosedHandCursor);
    e->accept();
    return;
  }
  QChartView::mousePressEvent(e);
}

void LinkedChartView::mouseMoveEvent(QMouseEvent* e) {
  if (dragging_) {
    const double w = chart()->plotArea().width();
    if (w > 0) {
      const double d = (drag_range_.second - drag_range_.first) * (e->position().x() - drag_x_px_) / w;
      emit xRangeRequested(drag_range_.first - d, drag_range_.second - d);
    }
    e->accept();
    return;
  }
  QChartView::mouseMoveEvent(e);
}

void LinkedChartView::mouseReleaseEvent(QMouseEvent* e) {
  if (dragging_ && e->button() == Qt::LeftButton) {
    dragging_ = false;
    unsetCursor();
    e->accept();
    return;
  }
  QChartView::mouseReleaseEvent(e);
}

void LinkedChartView::mouseDoubleClickEvent(QMouseEvent* e) {
  emit resetRequested();
  e->accept();
}

void LinkedChartView::keyPressEvent(QKeyEvent* e) {
  const auto [x0, x1] = xRange();
  const double mid = (x0 + x1) / 2;
  switch (e->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal: zoomX(0.5, mid); break;
    case Qt::Key_Minus: zoomX(2.0, mid); break;
    case Qt::Key_Left: panX(-0.25); break;
    case Qt::Key_Right: panX(0.25); break;
    case Qt::Key_Home: emit resetRequested(); break;
    default: QChartView::keyPressEvent(e); return;
  }
  e->accept();
}

}  // namespace auv::ui
