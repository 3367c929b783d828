#include "widgets/weight_map_widget.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace auv::ui {

WeightMapWidget::WeightMapWidget(QWidget* parent) : QWidget(parent) {
  setObjectName("weight_map");
  setMinimumSize(600, 260);
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

  const double unit = 7.0;  // px per sqrt(kg): a 4.8 kg piece ~15 px
  for (const auto& pt : model_.points) {
    const QPointF at = toScreen(pt.x_m, pt.y_m, syp);
    p.setPen(QPen(Qt::black, 1));
    p.setBrush(QColor(150, 150, 150));
    const double r_inst = 6 + (pt.installed_kg > 0 ? std::sqrt(pt.installed_kg) * 2 : 0);
    p.drawEllipse(at, r_inst, r_inst);
    // Pieces to add/remove in a row beside the point, away from the centreline.
    double x = at.x() + r_inst + 4;
    const double yrow = at.y() + (pt.y_m >= 0 ? 4 : -4 - unit * std::sqrt(4.8));
    for (const auto& ch : pt.change) {
      const double side = unit * std::sqrt(ch.size_kg);
      const QColor col = ch.count > 0 ? QColor(46, 160, 67) : QColor(210, 50, 50);
      for (int k = 0; k < std::abs(ch.count); ++k) {
        p.setBrush(col);
        p.drawRect(QRectF(x, yrow, side, side));
        x += side + 3;
      }
    }
    const QString text = QString("%1: %2%3 kg")
                             .arg(QString::fromStdString(pt.label))
                             .arg(pt.change_kg >= 0 ? "+" : "")
                             .arg(pt.change_kg, 0, 'f', 1);
    p.setPen(palette().text().color());
    const double ty = pt.y_m >= 0 ? at.y() + unit * std::sqrt(4.8) + 22 : at.y() - unit * std::sqrt(4.8) - 10;
    p.drawText(QPointF(at.x() - 40, ty), text);
  }
}

}  // namespace auv::ui
