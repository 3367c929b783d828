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

namespace {

// One label in a band above or below the hull: the rows nearest the hull
// fill first, and a label that would touch another (or a fixed caption)
// goes one row further out, so no two texts ever overlap.
struct LabelSlot {
  QString text;
  double width = 0.0;
  double x = 0.0;  // left edge
  bool above = true;
  int row = 0;
};

void placeInRows(std::vector<LabelSlot*>& side, std::vector<std::vector<std::pair<double, double>>>& rows) {
  constexpr double kGap = 14.0;
  std::sort(side.begin(), side.end(), [](const LabelSlot* a, const LabelSlot* b) { return a->x < b->x; });
  for (LabelSlot* l : side) {
    for (int r = 0;; ++r) {
      if (static_cast<std::size_t>(r) >= rows.size()) rows.emplace_back();
      bool free = true;
      for (const auto& [a, b] : rows[static_cast<std::size_t>(r)])
        if (l->x < b + kGap && l->x + l->width > a - kGap) free = false;
      if (free) {
        rows[static_cast<std::size_t>(r)].emplace_back(l->x, l->x + l->width);
        l->row = r;
        break;
      }
    }
  }
}

}  // namespace

void WeightMapWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const WeightMapLayout layout =
      drawWeightMap(p, QRectF(rect()), model_, {font(), palette().base().color(), palette().text().color()});
  label_rects_ = layout.labels;
  hull_rect_ = layout.hull;
}

WeightMapLayout drawWeightMap(QPainter& p, const QRectF& area, const WeightMapModel& model, const WeightMapStyle& style) {
  WeightMapLayout layout;
  p.save();
  p.translate(area.topLeft());
  p.setFont(style.font);
  const double W = area.width(), H = area.height();
  p.fillRect(QRectF(0, 0, W, H), style.background);
  if (model.length_m <= 0) {
    p.restore();
    return layout;
  }
  // Hull outline spans x in [-L/2, L/2]; the hull is drawn wider than true
  // scale across (y) so that the points and their pieces stay readable. The
  // point labels sit in bands above and below the hull, never on it.
  const double margin = 40;
  const double sx = (W - 2 * margin) / model.length_m;
  const double cx = W / 2.0;
  const double ymax_pts = [&] {
    double m = model.diameter_m / 2.0;
    for (const auto& pt : model.points) m = std::max(m, std::abs(pt.y_m));
    return m;
  }();
  // Screen offset of each point from the centreline in units of the hull's
  // half width: points scaled to sit inside the hull, and points at the same
  // x and y in this top view (e.g. a glider's upper and lower aft bottles)
  // spread apart so each stays readable.
  std::vector<double> across(model.points.size());
  for (std::size_t i = 0; i < model.points.size(); ++i) {
    const auto& pt = model.points[i];
    int before = 0, same = 0;
    for (std::size_t j = 0; j < model.points.size(); ++j) {
      const auto& o = model.points[j];
      if (std::abs(o.x_m - pt.x_m) < 1e-3 && std::abs(o.y_m - pt.y_m) < 1e-3) {
        ++same;
        if (j < i) ++before;
      }
    }
    across[i] = 0.8 * pt.y_m / ymax_pts + (before - (same - 1) / 2.0) * 0.9;
  }

  // Labels: "<point>: <change> (<installed> → <after>)", placed in rows.
  const QFontMetricsF fm(style.font, p.device());
  const double label_h = fm.height() + 4;
  std::vector<LabelSlot> labels(model.points.size());
  std::vector<LabelSlot*> top, bottom;
  for (std::size_t i = 0; i < model.points.size(); ++i) {
    const auto& pt = model.points[i];
    const bool g = model.grams;
    const double after = pt.installed_kg + pt.change_kg;
    // installed_kg NaN: what the place holds is not known (a glider's bottles).
    const QString amounts = !std::isfinite(pt.installed_kg) ? QString()
                          : g ? QString("%1 → %2").arg(fixed(std::round(pt.installed_kg * 1000.0), 0))
                                    .arg(fixed(std::round(after * 1000.0), 0))
                              : QString("%1 → %2").arg(fixed(pt.installed_kg, 1)).arg(fixed(after, 1));
    LabelSlot& l = labels[i];
    l.text = amounts.isEmpty() ? QString("%1: %2").arg(QString::fromStdString(pt.label), massText(pt.change_kg, g, true))
                               : QString("%1: %2 (%3)").arg(QString::fromStdString(pt.label), massText(pt.change_kg, g, true), amounts);
    l.width = fm.horizontalAdvance(l.text) + 6;
    l.x = std::clamp(cx + pt.x_m * sx - l.width / 2, 2.0, std::max(2.0, W - 2.0 - l.width));
    l.above = across[i] < 0;
    (l.above ? top : bottom).push_back(&l);
  }
  // Fixed captions take their place in the first row of each band.
  const QString bow = WeightMapWidget::tr("bow ▶"), stbd = WeightMapWidget::tr("starboard ▼");
  const double bow_w = fm.horizontalAdvance(bow) + 6, stbd_w = fm.horizontalAdvance(stbd) + 6;
  std::vector<std::vector<std::pair<double, double>>> rows_top{{{W - margin - bow_w, W - margin}}};
  std::vector<std::vector<std::pair<double, double>>> rows_bottom{{{margin, margin + stbd_w}}};
  placeInRows(top, rows_top);
  placeInRows(bottom, rows_bottom);
  const double band_top = static_cast<double>(rows_top.size()) * label_h + 8;
  const double band_bottom = static_cast<double>(rows_bottom.size()) * label_h + 8;
  const double half_w = std::max(20.0, std::min(W * 0.12, (H - band_top - band_bottom) / 2.0));
  const QPointF c(cx, band_top + (H - band_top - band_bottom) / 2.0);
  auto labelRect = [&](const LabelSlot& l) {
    const double y = l.above ? c.y() - half_w - 6 - (l.row + 1) * label_h : c.y() + half_w + 6 + l.row * label_h;
    return QRectF(l.x, y, l.width, label_h);
  };

  QPainterPath hull;
  const double L = model.length_m * sx;
  hull.addRoundedRect(QRectF(c.x() - L / 2, c.y() - half_w, L, 2 * half_w), half_w, half_w);
  p.setPen(QPen(style.text, 2));
  p.setBrush(QColor(230, 236, 242));
  p.drawPath(hull);
  p.drawText(labelRect({bow, bow_w, W - margin - bow_w, true, 0}), Qt::AlignCenter, bow);
  p.drawText(labelRect({stbd, stbd_w, margin, false, 0}), Qt::AlignCenter, stbd);

  // Centre of buoyancy marker.
  const QPointF cb(c.x() + model.cb_x_m * sx, c.y() + model.cb_y_m * half_w / (model.diameter_m / 2.0));
  p.setPen(QPen(QColor(30, 90, 200), 2));
  p.drawLine(cb + QPointF(-8, 0), cb + QPointF(8, 0));
  p.drawLine(cb + QPointF(0, -8), cb + QPointF(0, 8));
  p.drawText(cb + QPointF(6, -6), WeightMapWidget::tr("CB"));

  std::vector<QPointF> at(model.points.size());
  for (std::size_t i = 0; i < model.points.size(); ++i) {
    at[i] = QPointF(c.x() + model.points[i].x_m * sx, c.y() + across[i] * half_w);
  }
  // Leader lines first, so circles and squares sit on top of them.
  p.setPen(QPen(QColor(120, 120, 120), 1, Qt::DotLine));
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const QRectF r = labelRect(labels[i]);
    const QPointF anchor(std::clamp(at[i].x(), r.left() + 4, r.right() - 4), labels[i].above ? r.bottom() : r.top());
    p.drawLine(anchor, at[i]);
  }

  const double unit = model.px_per_sqrt_kg;
  QFont small = style.font;
  small.setPointSizeF(style.font.pointSizeF() * 0.85);
  for (std::size_t i = 0; i < model.points.size(); ++i) {
    const auto& pt = model.points[i];
    p.setPen(QPen(Qt::black, 1));
    p.setBrush(QColor(150, 150, 150));
    const double installed = model.grams ? pt.installed_kg * 30.0 : pt.installed_kg;  // grams read like kg
    const double r_inst = 6 + (installed > 0 ? std::min(std::sqrt(installed) * 2, 14.0) : 0);
    p.drawEllipse(at[i], r_inst, r_inst);
    // Pieces to add/remove in a row to the right of the point, centred on it.
    double x = at[i].x() + r_inst + 4;
    for (const auto& b : pt.blocks()) {
      const double side = std::max(5.0, unit * std::sqrt(b.mass_kg));
      const QColor col = b.add ? QColor(46, 160, 67) : QColor(210, 50, 50);
      p.setPen(QPen(Qt::black, 1));
      p.setBrush(col);
      const QRectF sq(x, at[i].y() - side / 2, side, side);
      p.drawRect(sq);
      x += side + 3;
      if (b.pieces > 1) {
        p.setPen(style.text);
        p.setFont(small);
        const QString n = QString("×%1").arg(b.pieces);
        p.drawText(QPointF(x, sq.bottom() - 2), n);
        x += QFontMetricsF(small, p.device()).horizontalAdvance(n) + 4;
        p.setFont(style.font);
      }
    }
  }
  p.setPen(style.text);
  for (const auto& l : labels) {
    const QRectF r = labelRect(l);
    p.fillRect(r, style.background);  // a leader line passing behind stays out of the text
    p.drawText(r, Qt::AlignCenter, l.text);
    layout.labels.push_back(r.translated(area.topLeft()));
  }
  layout.hull = hull.boundingRect().translated(area.topLeft());
  p.restore();
  return layout;
}

}  // namespace auv::ui
