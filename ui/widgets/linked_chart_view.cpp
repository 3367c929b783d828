#include "widgets/linked_chart_view.h"

#include <QGraphicsLineItem>
#include <QGraphicsItem>
#include <QPainter>
#include <QPolygonF>
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

// Paints the bands inside the plot area in one go (no pen, translucent
// green, under the grid), clipped to the area.
class LinkedChartView::BandsItem : public QGraphicsItem {
 public:
  explicit BandsItem(LinkedChartView& view) : view_(view) { setZValue(1.5); }
  QRectF boundingRect() const override { return area_; }
  void setArea(const QRectF& a) {
    if (a == area_) {
      update();
      return;
    }
    prepareGeometryChange();
    area_ = a;
  }
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override {
    p->setPen(Qt::NoPen);
    p->setBrush(QColor(70, 170, 90, 45));
    for (const auto& [x0, x1] : view_.bands_) {
      const double l = std::max(view_.xToPixel(x0), area_.left()), r = std::min(view_.xToPixel(x1), area_.right());
      if (r > l) p->drawRect(QRectF(l, area_.top(), r - l, area_.height()));
    }
  }

 private:
  LinkedChartView& view_;
  QRectF area_;
};

// One series' min/max envelope: a bar per column, clipped to the plot area.
class LinkedChartView::EnvelopeItem : public QGraphicsItem {
 public:
  explicit EnvelopeItem(QChart& chart) : chart_(chart) { setZValue(1.7); }
  QRectF boundingRect() const override { return area_; }
  void set(QList<QPointF> lower, QList<QPointF> upper, const QColor& color) {
    lower_ = std::move(lower);
    upper_ = std::move(upper);
    color_ = color;
    setVisible(!lower_.isEmpty() && lower_.size() == upper_.size());
    update();
  }
  void setArea(const QRectF& a) {
    if (a == area_) {
      update();
      return;
    }
    prepareGeometryChange();
    area_ = a;
  }
  const QList<QPointF>& lower() const { return lower_; }
  const QList<QPointF>& upper() const { return upper_; }
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override {
    if (lower_.isEmpty()) return;
    p->setClipRect(area_);
    // Column k spans from half-way to its left neighbour to half-way to its
    // right one, on whole pixels: neither gaps nor doubly shaded stripes.
    const qsizetype n = lower_.size();
    std::vector<double> x(static_cast<std::size_t>(n));
    for (qsizetype k = 0; k < n; ++k)
      x[static_cast<std::size_t>(k)] = chart_.mapToPosition(QPointF((lower_[k].x() + upper_[k].x()) / 2.0, 0.0)).x();
    const auto edge = [&](qsizetype k) {  // left edge of column k
      const auto i = static_cast<std::size_t>(k);
      if (k == 0) return std::floor(x[0] - 0.5);
      if (k == n) return std::floor(x[i - 1] + 0.5) + 1.0;
      return std::floor((x[i - 1] + x[i]) / 2.0);
    };
    // Columns that start on the same pixel are merged (their extremes
    // joined), so no pixel is shaded twice and no extreme is lost.
    struct Bar {
      double l, r, top, bottom;
    };
    std::vector<Bar> bars;
    bars.reserve(static_cast<std::size_t>(n));
    for (qsizetype k = 0; k < n; ++k) {
      const double y0 = chart_.mapToPosition(QPointF(0.0, lower_[k].y())).y();
      const double y1 = chart_.mapToPosition(QPointF(0.0, upper_[k].y())).y();
      const double l = edge(k), r = std::max(edge(k + 1), l + 1.0);
      const double top = std::floor(std::min(y0, y1)), bottom = std::max(std::ceil(std::max(y0, y1)), top + 1.0);
      if (!bars.empty() && l <= bars.back().l) {
        Bar& b = bars.back();
        b.r = std::max(b.r, r);
        b.top = std::min(b.top, top);
        b.bottom = std::max(b.bottom, bottom);
        continue;
      }
      if (!bars.empty()) bars.back().r = std::min(bars.back().r, l);
      bars.push_back({l, r, top, bottom});
    }
    for (const Bar& b : bars) p->fillRect(QRectF(b.l, b.top, b.r - b.l, b.bottom - b.top), color_);
    // The envelope's edges in a stronger tone: a one-sample spike is a
    // 1 px bar, too faint alone.
    QPolygonF top, bottom;
    for (const Bar& b : bars) {
      top << QPointF(b.l + 0.5, b.top + 0.5);
      bottom << QPointF(b.l + 0.5, b.bottom - 0.5);
    }
    QColor edge_color = color_;
    edge_color.setAlpha(std::min(255, color_.alpha() * 2 + 40));
    p->setPen(QPen(edge_color, 1.0));
    p->drawPolyline(top);
    p->drawPolyline(bottom);
  }

 private:
  QChart& chart_;
  QRectF area_;
  QList<QPointF> lower_, upper_;
  QColor color_;
};

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
  for (auto*& e : envelopes_) {
    e = new EnvelopeItem(*chart);
    e->setVisible(false);
    scene()->addItem(e);
  }
  bands_item_ = new BandsItem(*this);
  bands_item_->setVisible(false);
  scene()->addItem(bands_item_);
  connect(chart, &QChart::plotAreaChanged, this, [this] { layoutOverlays(); });
  const auto axes = chart->axes(Qt::Horizontal);
  if (auto* x = axes.isEmpty() ? nullptr : qobject_cast<QValueAxis*>(axes.first()))
    connect(x, &QValueAxis::rangeChanged, this, [this] { layoutOverlays(); });
  const auto ys = chart->axes(Qt::Vertical);
  if (auto* y = ys.isEmpty() ? nullptr : qobject_cast<QValueAxis*>(ys.first()))
    connect(y, &QValueAxis::rangeChanged, this, [this] { layoutOverlays(); });
}

double LinkedChartView::xToPixel(double x) const {
  const QRectF a = chart()->plotArea();
  const auto [x0, x1] = xRange();
  return a.left() + (x - x0) / (x1 - x0) * a.width();
}

void LinkedChartView::setBands(const std::vector<std::pair<double, double>>& bands, bool numbered) {
  bands_ = bands;
  numbered_ = numbered;
  layoutOverlays();
}

void LinkedChartView::setEnvelope(int slot, QList<QPointF> lower, QList<QPointF> upper, const QColor& color) {
  EnvelopeItem* e = envelopes_[static_cast<std::size_t>(slot)];
  e->set(std::move(lower), std::move(upper), color);
  e->setArea(chart()->plotArea());
}

const QList<QPointF>& LinkedChartView::envelopeEdge(int slot, bool upper) const {
  const EnvelopeItem* e = envelopes_[static_cast<std::size_t>(slot)];
  return upper ? e->upper() : e->lower();
}

int LinkedChartView::visibleBandCount() const {
  const auto [x0, x1] = xRange();
  return static_cast<int>(
      std::count_if(bands_.begin(), bands_.end(), [&](const auto& b) { return b.second > x0 && b.first < x1; }));
}

void LinkedChartView::setCrosshair(std::optional<double> x) {
  crosshair_x_ = x;
  layoutOverlays();
}

void LinkedChartView::layoutOverlays() {
  const QRectF a = chart()->plotArea();
  const auto [x0, x1] = xRange();
  const bool ok = a.width() > 0 && x1 > x0;
  for (EnvelopeItem* e : envelopes_) e->setArea(a);
  bands_item_->setVisible(ok && !bands_.empty());
  if (ok) bands_item_->setArea(a);
  std::size_t used = 0;
  for (std::size_t k = 0; numbered_ && ok && k < bands_.size(); ++k) {
    const double l = std::max(xToPixel(bands_[k].first), a.left()), r = std::min(xToPixel(bands_[k].second), a.right());
    // Numbers take ~8 px a digit: narrower bands (most of a long log at
    // full view) go without one, as before.
    if (r - l < 10.0) continue;
    const QString text = QString::number(k + 1);
    if (used == labels_.size()) {
      auto* label = new QGraphicsSimpleTextItem;
      label->setBrush(QColor(30, 110, 50));
      label->setZValue(1.6);
      scene()->addItem(label);
      labels_.push_back(label);
    }
    QGraphicsSimpleTextItem* label = labels_[used];
    if (label->text() != text) label->setText(text);
    const double w = label->boundingRect().width();
    if (r - l <= w + 2) continue;
    label->setPos((l + r - w) / 2, a.top() + 2);
    label->setVisible(true);
    ++used;
  }
  for (std::size_t k = used; k < labels_.size(); ++k) labels_[k]->setVisible(false);
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
