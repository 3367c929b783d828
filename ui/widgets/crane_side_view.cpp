#include "widgets/crane_side_view.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "widgets/inputs.h"

namespace auv::ui {

CraneSideView::CraneSideView(QWidget* parent) : QWidget(parent) {
  setObjectName("crane_side_view");
  setMinimumSize(minimumSizeHint());
  setToolTip(tr("Side view, bow to the right: where each crane scale hangs and what it reads."));
}

void CraneSideView::setData(const CraneSideViewData& d) {
  data_ = d;
  update();
}

void CraneSideView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), palette().base());
  if (data_.length_m <= 0 || data_.diameter_m <= 0) return;
  const QFontMetricsF fm(font());
  const double line = fm.height();
  // x to scale along the hull; the hull's height keeps its true proportion
  // unless the widget is too low for it.
  const double margin = 50;
  const double sx = (width() - 2 * margin) / data_.length_m;
  const double cx = width() / 2.0;
  auto X = [&](double x_m) { return cx + x_m * sx; };
  const double hook_y = 8 + line;
  const double bar_y = hook_y + 28;
  const double scale_y = bar_y + 12;    // top of the scale boxes on the ropes
  const double scale_h = 2 * line + 6;  // room for the two readings beside them
  const double hull_top = scale_y + scale_h + 8;
  const double bottom_text = line + 8;
  const double hull_h = std::max(24.0, std::min(data_.diameter_m * sx, height() - hull_top - bottom_text - 4));
  const QColor ink = palette().text().color();

  // Hull outline (side view), CB and CG.
  QPainterPath hull;
  const double L = data_.length_m * sx;
  hull.addRoundedRect(QRectF(cx - L / 2, hull_top, L, hull_h), hull_h / 2, hull_h / 2);
  p.setPen(QPen(ink, 2));
  p.setBrush(QColor(230, 236, 242));
  p.drawPath(hull);
  const double mid = hull_top + hull_h / 2;
  p.drawText(QRectF(cx + L / 2 - 80, mid - line / 2, 70, line), Qt::AlignRight | Qt::AlignVCenter, tr("bow ▶"));
  const QPointF cb(X(data_.cb_x_m), mid);
  p.setPen(QPen(QColor(30, 90, 200), 2));
  p.drawLine(cb + QPointF(-7, 0), cb + QPointF(7, 0));
  p.drawLine(cb + QPointF(0, -7), cb + QPointF(0, 7));
  p.drawText(cb + QPointF(-22, -6), tr("CB"));
  if (data_.cg_x_m) {
    const QPointF cg(X(*data_.cg_x_m), mid);
    p.setPen(QPen(QColor(200, 40, 40), 2));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(cg, 6, 6);
    p.drawLine(cg + QPointF(-6, 0), cg + QPointF(6, 0));
    p.drawText(cg + QPointF(9, 14), tr("CG"));
  }

  // Hook, spreader bar and the two ropes with their scales.
  const double xf = X(data_.rope_fore_x_m), xa = X(data_.rope_aft_x_m);
  const QPointF hook(cx, hook_y);
  p.setPen(QPen(ink, 1.5));
  p.setBrush(Qt::NoBrush);
  p.drawLine(hook, QPointF(xa, bar_y));
  p.drawLine(hook, QPointF(xf, bar_y));
  p.setPen(QPen(ink, 3));
  p.drawLine(QPointF(std::min(xa, xf), bar_y), QPointF(std::max(xa, xf), bar_y));
  p.setPen(QPen(ink, 1.5));
  p.drawEllipse(hook + QPointF(0, -5), 5, 5);
  p.drawText(QPointF(cx + 12, hook_y), tr("hook: %1 kg").arg(fixed(data_.total_kg, 1)));

  struct Station {
    double x;
    const char* a;
    const char* b;
    double ra, rb;
    bool fore;
  };
  const Station stations[2] = {{xf, QT_TR_NOOP("FS"), QT_TR_NOOP("FP"), data_.scales_kg[0], data_.scales_kg[1], true},
                               {xa, QT_TR_NOOP("AS"), QT_TR_NOOP("AP"), data_.scales_kg[2], data_.scales_kg[3], false}};
  for (const auto& s : stations) {
    p.setPen(QPen(ink, 1.5));
    p.drawLine(QPointF(s.x, bar_y), QPointF(s.x, hull_top));
    const QRectF box(s.x - 8, scale_y, 16, scale_h);
    p.setBrush(QColor(255, 214, 102));
    p.drawRoundedRect(box, 3, 3);
    p.setBrush(Qt::NoBrush);
    // Readings beside the scale, on the side away from the hook.
    const QString ta = tr("%1 %2 kg").arg(tr(s.a)).arg(fixed(s.ra, 1));
    const QString tb = tr("%1 %2 kg").arg(tr(s.b)).arg(fixed(s.rb, 1));
    const double w = std::max(fm.horizontalAdvance(ta), fm.horizontalAdvance(tb)) + 4;
    const bool right = s.x >= cx;
    const double tx = right ? box.right() + 6 : box.left() - 6 - w;
    const Qt::Alignment al = (right ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter;
    p.drawText(QRectF(tx, scale_y + 2, w, line), al, ta);
    p.drawText(QRectF(tx, scale_y + 4 + line, w, line), al, tb);
  }

  // Where the ropes are, in the profile's x (forward positive).
  const QString stations_text =
      data_.rope_fore_x_m > data_.rope_aft_x_m
          ? tr("Ropes at x = %1 m (fore) and %2 m (aft); starboard and port scales hang one behind the other.")
                .arg(fixed(data_.rope_fore_x_m, 3))
                .arg(fixed(data_.rope_aft_x_m, 3))
          : tr("Enter where the ropes are: the fore rope's x must be forward of (greater than) the aft rope's.");
  p.setPen(ink);
  p.drawText(QRectF(8, height() - line - 4, width() - 16, line), Qt::AlignLeft | Qt::AlignVCenter,
             fm.elidedText(stations_text, Qt::ElideRight, width() - 16));
}

}  // namespace auv::ui
