#include "widgets/linked_chart_view.h"

#include <QGraphicsLineItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPen>
#include <QWheelEvent>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <cmath>

namespace auv::ui {

LinkedChartView::LinkedChartView(QChart* chart, QWidget* parent) : QChartView(chart, parent) {
  setFocusPolicy(Qt::StrongFocus);
  // No anti-aliasing: with ~2 points per pixel column it hardly shows, and
  // it doubles the cost of every repaint of a zoomed or panned chart.
  setRenderHint(QPainter::Antialiasing, false);
  setToolTip(tr("Wheel or +/-: zoom in time. Drag or arrow keys: move in time. Double-click or Home: whole log. "
                "All three charts follow."));
  // Move events without a button pressed drive the crosshair.
  viewport()->setMouseTracking(true);
  // Qt Charts stacks plot area (0), shades, grid, axes and series (4) upwards:
  // bands sit on the plot background under the grid, the crosshair on top.
  crosshair_ = new QGraphicsLineItem;
  QPen pen(QColor(90, 90, 90));
  pen.setWidth(1);
  crosshair_->setPen(pen);
  crosshair_->setZValue(20);
  crosshair_->setVisible(false);
  scene()->addItem(crosshair_);
  connect(chart, &QChart::plotAreaChanged, this, [this] { layoutOverlays(); });
  const auto axes = chart->axes(Qt::Horizontal);
  if (auto* x = axes.isEmpty() ? nullptr : qobject_cast<QValueAxis*>(axes.first()))
    connect(x, &QValueAxis::rangeChanged, this, [this] { layoutOverlays(); });
}

double LinkedChartView::xToPixel(double x) const {
  const QRectF a = chart()->plotArea();
  const auto [x0, x1] = xRange();
  return a.left() + (x - x0) / (x1 - x0) * a.width();
}

void LinkedChartView::setBands(const std::vector<std::pair<double, double>>& bands, bool numbered) {
  for (Band& b : bands_) {
    delete b.rect;
    delete b.label;
  }
  bands_.clear();
  int k = 0;
  for (const auto& [x0, x1] : bands) {
    Band b{x0, x1, new QGraphicsRectItem, nullptr};
    b.rect->setBrush(QColor(70, 170, 90, 45));
    b.rect->setPen(Qt::NoPen);
    b.rect->setZValue(1.5);
    scene()->addItem(b.rect);
    if (numbered) {
      b.label = new QGraphicsSimpleTextItem(QString::number(++k));
      b.label->setBrush(QColor(30, 110, 50));
      b.label->setZValue(1.6);
      scene()->addItem(b.label);
    }
    bands_.push_back(b);
  }
  layoutOverlays();
}

int LinkedChartView::visibleBandCount() const {
  const auto [x0, x1] = xRange();
  return static_cast<int>(std::count_if(bands_.begin(), bands_.end(), [&](const Band& b) { return b.x1 > x0 && b.x0 < x1; }));
}

void LinkedChartView::setCrosshair(std::optional<double> x) {
  crosshair_x_ = x;
  layoutOverlays();
}

void LinkedChartView::layoutOverlays() {
  const QRectF a = chart()->plotArea();
  const auto [x0, x1] = xRange();
  const bool ok = a.width() > 0 && x1 > x0;
  for (Band& b : bands_) {
    const double l = std::max(xToPixel(b.x0), a.left()), r = std::min(xToPixel(b.x1), a.right());
    const bool shown = ok && r > l;
    b.rect->setVisible(shown);
    if (b.label) b.label->setVisible(shown && r - l > b.label->boundingRect().width() + 2);
    if (!shown) continue;
    b.rect->setRect(QRectF(l, a.top(), r - l, a.height()));
    if (b.label) b.label->setPos((l + r - b.label->boundingRect().width()) / 2, a.top() + 2);
  }
  const bool cross = ok && crosshair_x_ && *crosshair_x_ >= x0 && *crosshair_x_ <= x1;
  crosshair_->setVisible(cross);
  if (cross) {
    const double px = std::round(xToPixel(*crosshair_x_)) + 0.5;
    crosshair_->setLine(px, a.top(), px, a.bottom());
  }
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
  if (!dragging_) {
    const QRectF a = chart()->plotArea();
    if (a.contains(e->position())) emit hovered(chart()->mapToValue(e->position()).x());
    else emit hoverLeft();
  }
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

void LinkedChartView::leaveEvent(QEvent* e) {
  emit hoverLeft();
  QChartView::leaveEvent(e);
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
