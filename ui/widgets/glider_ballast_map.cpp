#include "widgets/glider_ballast_map.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "widgets/inputs.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

double num(const nlohmann::json& j, const char* k, double fallback) {
  return j.contains(k) && j[k].is_number() ? j[k].get<double>() : fallback;
}

QString gramsText(double g) {
  const double r = std::round(g);
  return r > 0 ? QString("+%1 g").arg(fixed(r, 0)) : QString("%1 g").arg(fixed(r == 0.0 ? 0.0 : r, 0));
}

QColor changeColour(double g) {
  if (std::round(g) > 0) return QColor(0x1b, 0x7f, 0x3b);
  if (std::round(g) < 0) return QColor(0xb0, 0x00, 0x20);
  return QColor(0x70, 0x70, 0x70);
}

// Labels in rows of a band above or below a view: each goes to the first row
// where it does not overlap one already placed.
struct Band {
  double top = 0.0;
  double row_h = 16.0;
  int direction = 1;  // +1 rows go down from `top`, -1 up
  std::vector<std::vector<QRectF>> rows;
  QRectF place(double centre_x, double w, const QRectF& bounds) {
    double x = std::clamp(centre_x - w / 2, bounds.left(), bounds.right() - w);
    for (std::size_t r = 0;; ++r) {
      if (r == rows.size()) rows.emplace_back();
      const double y = direction > 0 ? top + static_cast<double>(r) * row_h : top - static_cast<double>(r + 1) * row_h;
      const QRectF rect(x, y, w, row_h);
      const bool clash = std::any_of(rows[r].begin(), rows[r].end(),
                                     [&](const QRectF& o) { return o.adjusted(-6, 0, 6, 0).intersects(rect); });
      if (!clash) {
        rows[r].push_back(rect);
        return rect;
      }
    }
  }
};

// One view: the hull from the side or from above, the places on it, the
// labels in bands. `across` picks the cross coordinate (y from above, z from
// the side); negative values are drawn (and labelled) above the hull.
void drawView(QPainter& p, const QRectF& area, const GliderMapModel& m, bool side, const QFont& font,
              std::vector<QRectF>& labels) {
  const QFontMetricsF fm(font);
  const double rowH = fm.height() + 2;
  p.setFont(font);
  p.setPen(Qt::black);
  const QString title = side ? GliderBallastMap::tr("Side view (bow to the right, keel down)")
                             : GliderBallastMap::tr("Top view (bow to the right, starboard down)");
  p.drawText(QPointF(area.left(), area.top() + fm.ascent()), title);
  const double L = m.length_m > 0 ? m.length_m : 1.5, D = m.diameter_m > 0 ? m.diameter_m : 0.22;
  // Rows for labels above and below: as many as places on that side, so
  // labels never spill into the other view.
  int above = 0, below = 0;
  double extent = D / 2;  // half-height of what is drawn: hull, or places outside it (wing rails)
  for (const auto& pl : m.places) {
    const double c = side ? pl.z_m : pl.y_m;
    (c < 0 ? above : below)++;
    extent = std::max(extent, std::abs(c) + 0.015);
  }
  const double viewTop = area.top() + rowH;
  const double hullSpace = std::max(30.0, area.height() - rowH - (std::max(above, 1) + std::max(below, 1)) * rowH - 8);
  const double scale = std::min(area.width() * 0.62 / L, hullSpace / (2 * extent));
  const double cx = area.center().x(), cy = viewTop + std::max(above, 1) * rowH + 4 + hullSpace / 2;
  auto toPx = [&](double x, double c) { return QPointF(cx + x * scale, cy + c * scale); };
  // Hull: a cylinder with rounded nose and tail; from above also the wings
  // (sketched to the places' reach, not to scale).
  const QRectF hull(cx - L / 2 * scale, cy - D / 2 * scale, L * scale, D * scale);
  p.setPen(QPen(QColor(0x40, 0x40, 0x40), 1.5));
  p.setBrush(QColor(0xf2, 0xf2, 0xf2));
  if (!side && extent > D / 2 + 0.02) {
    QPolygonF wings;
    wings << toPx(0.02, -D / 2) << toPx(-0.16, -extent) << toPx(-0.26, -extent) << toPx(-0.2, -D / 2);
    p.drawPolygon(wings);
    QPolygonF w2;
    for (const QPointF& pt : wings) w2 << QPointF(pt.x(), 2 * cy - pt.y());
    p.drawPolygon(w2);
  }
  p.drawRoundedRect(hull, D * scale * 0.5, D * scale * 0.5);
  p.setBrush(Qt::NoBrush);
  Band up{cy - extent * scale - 4, rowH, -1, {}};
  Band down{cy + extent * scale + 4, rowH, 1, {}};
  for (const GliderMapPlace& pl : m.places) {
    const double c = side ? pl.z_m : pl.y_m;
    const QPointF at = toPx(pl.x_m, c);
    const QColor col = changeColour(pl.add_g);
    const double r = 5.0 + std::min(7.0, std::sqrt(std::abs(pl.add_g)) * 0.6);
    p.setPen(QPen(col, 1.5));
    p.setBrush(col.lighter(std::round(pl.add_g) == 0 ? 170 : 150));
    p.drawEllipse(at, r, r);
    p.setBrush(Qt::NoBrush);
    QString text = QString("%1: %2").arg(pl.label, gramsText(pl.add_g));
    if (pl.after_g >= 0) text += QString(" (→ %1 g)").arg(fixed(pl.after_g, 0));
    const double w = fm.horizontalAdvance(text) + 6;
    Band& b = c < 0 ? up : down;
    const QRectF rect = b.place(at.x(), w, area);
    p.setPen(QPen(QColor(0x90, 0x90, 0x90), 1.0));
    p.drawLine(at, QPointF(std::clamp(at.x(), rect.left() + 3, rect.right() - 3), c < 0 ? rect.bottom() : rect.top()));
    p.setPen(col);
    p.drawText(rect, Qt::AlignCenter, text);
    labels.push_back(rect);
  }
}

}  // namespace

GliderMapModel makeGliderMapModel(const VehicleProfile& v, const nlohmann::json& plan) {
  GliderMapModel m;
  m.length_m = v.hull.length_m;
  m.diameter_m = v.hull.diameter_m;
  for (const auto& pt : plan.value("points", nlohmann::json::array())) {
    const std::string name = pt.value("name", std::string());
    const AdjustmentPoint* ap = v.findPoint(name);
    GliderMapPlace pl;
    pl.label = q(ap ? ap->label : pt.value("label", name));
    if (ap) {
      pl.x_m = ap->position_m.x();
      pl.y_m = ap->position_m.y();
      pl.z_m = ap->position_m.z();
    }
    pl.add_g = num(pt, "add_g", 0.0);
    pl.after_g = num(pt, "after_g", -1.0);
    pl.capacity_g = num(pt, "capacity_g", -1.0);
    m.places.push_back(pl);
  }
  if (plan.contains("seaglider")) {
    const auto& s = plan["seaglider"];
    if (m.places.empty() && !v.points.empty()) {
      // No lead to change: the lead place is still shown, with 0 g.
      GliderMapPlace pl;
      pl.label = q(v.points.front().label);
      pl.x_m = v.points.front().position_m.x();
      pl.z_m = v.points.front().position_m.z();
      m.places.push_back(pl);
    }
    m.note = GliderBallastMap::tr("$C_VBD %1 → %2").arg(fixed(num(s, "C_VBD_old", 0), 0)).arg(fixed(num(s, "C_VBD_new", 0), 0));
    const nlohmann::json sg = v.sections.contains("seaglider") ? v.sections["seaglider"] : nlohmann::json::object();
    const double c = num(s, "C_PITCH_new", NAN);
    if (c >= num(sg, "PITCH_MIN", -1e9) && c <= num(sg, "PITCH_MAX", 1e9))  // else the steps say why it stays
      m.note += GliderBallastMap::tr(", $C_PITCH %1 → %2").arg(fixed(num(s, "C_PITCH_old", 0), 0)).arg(fixed(num(s, "C_PITCH_new", 0), 0));
  } else if (m.places.empty()) {
    m.note = GliderBallastMap::tr("The log does not tell where the grams go on this glider (see the notes).");
  }
  return m;
}

std::vector<QRectF> drawGliderBallastMap(QPainter& p, const QRectF& area, const GliderMapModel& m, const QFont& font) {
  std::vector<QRectF> labels;
  p.save();
  p.setRenderHint(QPainter::Antialiasing);
  const QFontMetricsF fm(font);
  const double noteH = m.note.isEmpty() ? 0.0 : fm.height() + 4;
  const double h = (area.height() - noteH) / 2;
  drawView(p, QRectF(area.left(), area.top(), area.width(), h - 4), m, false, font, labels);
  drawView(p, QRectF(area.left(), area.top() + h, area.width(), h - 4), m, true, font, labels);
  if (!m.note.isEmpty()) {
    p.setPen(Qt::black);
    p.setFont(font);
    p.drawText(QRectF(area.left(), area.bottom() - noteH, area.width(), noteH), Qt::AlignLeft | Qt::AlignVCenter, m.note);
  }
  p.restore();
  return labels;
}

GliderBallastMap::GliderBallastMap(QWidget* parent) : QWidget(parent) {
  setObjectName("glider_map");
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void GliderBallastMap::setModel(GliderMapModel m) {
  model_ = std::move(m);
  update();
}

void GliderBallastMap::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), Qt::white);
  labels_ = drawGliderBallastMap(p, QRectF(rect()).adjusted(6, 4, -6, -4), model_, font());
}

}  // namespace auv::ui
