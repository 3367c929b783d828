#include "widgets/weight_map_widget.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <vector>

#include "widgets/inputs.h"

namespace auv::ui {

WeightMapWidget::WeightMapWidget(QWidget* parent) : QWidget(parent) {
  setObjectName("weight_map");
  setMinimumSize(600, 200);
  setToolTip(tr("Top view, bow to the right. Green: add, red: remove, grey: installed now."));
}

void WeightMapWidget::setModel(WeightMapModel model) {
  model_ = std::move(model);
  update();
}

void WeightMapWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), palette().base());
  if (model_.length_m <= 0) return;
  // Hull outline spans x in [-L/2, L/2]; the hull is drawn wider than true
  // scale across (y) so that the points and their pieces stay readable.
  const double margin = 40;
  const double sx = (width() - 2 * margin) / model_.length_m;
  const double half_w = std::min(height() * 0.32, width() * 0.12);
  const double sy = half_w / (model_.diameter_m / 2.0);
  const double ymax_pts = [&] {
    double m = model_.diameter_m / 2.0;
    for (const auto& pt : model_.points) m = std::max(m, std::abs(pt.y_m));
    return m;
  }();
  const double syp = half_w * 0.8 / ymax_pts;  // points scaled to sit inside the hull
  const QPointF c(width() / 2.0, height() / 2.0);
  auto toScreen = [&](double x, double y, double scale_y) { return QPointF(c.x() + x * sx, c.y() + y * scale_y); };

  QPainterPath hull;
  const double L = model_.length_m * sx;
  hull.addRoundedRect(QRectF(c.x() - L / 2, c.y() - half_w, L, 2 * half_w), half_w, half_w);
  p.setPen(QPen(palette().text().color(), 2));
  p.setBrush(QColor(230, 236, 242));
  p.drawPath(hull);
  p.drawText(QRectF(c.x() + L / 2 - 70, c.y() - half_w - 24, 70, 20), Qt::AlignRight, tr("bow ▶"));
  p.drawText(QRectF(c.x() - L / 2, c.y() + half_w + 4, 120, 20), Qt::AlignLeft, tr("starboard ▼"));

  // Centre of buoyancy marker.
  const QPointF cb = toScreen(model_.cb_x_m, model_.cb_y_m, sy);
  p.setPen(QPen(QColor(30, 90, 200), 2));
  p.drawLine(cb + QPointF(-8, 0), cb + QPointF(8, 0));
  p.drawLine(cb + QPointF(0, -8), cb + QPointF(0, 8));
  p.drawText(cb + QPointF(6, -6), tr("CB"));

  const double unit = model_.px_per_sqrt_kg;
  // Height reserved for a row of squares: the largest square, at least 15 px.
  double row_h = 15.0;
  for (const auto& pt : model_.points)
    for (const auto& b : pt.blocks()) row_h = std::max(row_h, unit * std::sqrt(b.mass_kg));
  // Points at the same x and y in this top view (e.g. a glider's upper and
  // lower aft bottles) are spread apart on screen so each stays readable.
  std::vector<QPointF> at(model_.points.size());
  for (std::size_t i = 0; i < model_.points.size(); ++i) {
    const auto& pt = model_.points[i];
    at[i] = toScreen(pt.x_m, pt.y_m, syp);
    int before = 0, same = 0;
    for (std::size_t j = 0; j < model_.points.size(); ++j) {
      const auto& o = model_.points[j];
      if (std::abs(o.x_m - pt.x_m) < 1e-3 && std::abs(o.y_m - pt.y_m) < 1e-3) {
        ++same;
        if (j < i) ++before;
      }
    }
    at[i].ry() += (before - (same - 1) / 2.0) * 0.9 * half_w;
  }
  QFont small = font();
  small.setPointSizeF(font().pointSizeF() * 0.85);
  for (std::size_t i = 0; i < model_.points.size(); ++i) {
    const auto& pt = model_.points[i];
    const bool below = at[i].y() >= c.y();  // labels away from the centreline
    p.setPen(QPen(Qt::black, 1));
    p.setBrush(QColor(150, 150, 150));
    const double installed = model_.grams ? pt.installed_kg * 30.0 : pt.installed_kg;  // grams read like kg
    const double r_inst = 6 + (installed > 0 ? std::min(std::sqrt(installed) * 2, 14.0) : 0);
    p.drawEllipse(at[i], r_inst, r_inst);
    // Pieces to add/remove in a row beside the point.
    double x = at[i].x() + r_inst + 4;
    const double yrow = at[i].y() + (below ? 4 : -4 - row_h);
    for (const auto& b : pt.blocks()) {
      const double side = std::max(5.0, unit * std::sqrt(b.mass_kg));
      const QColor col = b.add ? QColor(46, 160, 67) : QColor(210, 50, 50);
      p.setPen(QPen(Qt::black, 1));
      p.setBrush(col);
      const QRectF sq(x, below ? yrow : yrow + row_h - side, side, side);
      p.drawRect(sq);
      x += side + 3;
      if (b.pieces > 1) {
        p.setPen(palette().text().color());
        p.setFont(small);
        const QString n = QString("×%1").arg(b.pieces);
        p.drawText(QPointF(x, sq.bottom() - 2), n);
        x += QFontMetricsF(small).horizontalAdvance(n) + 4;
        p.setFont(font());
      }
    }
    const QString text = QString("%1: %2").arg(QString::fromStdString(pt.label), massText(pt.change_kg, model_.grams, true));
    p.setPen(palette().text().color());
    const double ty = below ? at[i].y() + row_h + 22 : at[i].y() - row_h - 10;
    p.drawText(QPointF(at[i].x() - 40, ty), text);
  }
}

}  // namespace auv::ui
