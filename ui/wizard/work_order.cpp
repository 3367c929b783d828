#include "wizard/work_order.h"

#include "wizard/advice_text.h"
#include "wizard/point_labels.h"

#include <QFile>
#include <QFileInfo>
#include <QFont>
#include <QFontMetricsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <algorithm>
#include <cmath>
#include <fstream>

#include "common/input_error.h"
#include "planning/installed_prediction.h"
#include "widgets/calibration_table.h"
#include "widgets/estimate_text.h"
#include "widgets/inputs.h"
#include "widgets/weight_map_widget.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

QString piecesText(const PointRecommendation& p, bool grams) {
  QStringList parts;
  std::vector<PieceCount> pieces = p.pieces;
  // Removals first, largest piece first: the order of the checklist.
  std::sort(pieces.begin(), pieces.end(), [](const PieceCount& a, const PieceCount& b) {
    return (a.count < 0) != (b.count < 0) ? a.count < 0 : a.size_kg > b.size_kg;
  });
  for (const auto& pc : pieces) {
    if (pc.count == 0) continue;
    parts << (pc.count > 0 ? WorkOrder::tr("add %1 × %2") : WorkOrder::tr("remove %1 × %2")).arg(std::abs(pc.count)).arg(massText(pc.size_kg, grams));
  }
  return parts.isEmpty() ? WorkOrder::tr("no change") : parts.join(", ");
}

QString inBand(bool ok) { return ok ? WorkOrder::tr("✓ in band") : WorkOrder::tr("✗ outside the band"); }

// "Vehicle", "Configuration", "Date" and, when given, payload and area.
QStringList headerLines(const WizardState& s, TimePoint now) {
  const VehicleProfile& v = *s.vehicle;
  QStringList h;
  h << WorkOrder::tr("Vehicle: %1 (%2)").arg(q(v.name), q(v.id))
    << WorkOrder::tr("Configuration: %1").arg(q(s.configuration_id))
    << WorkOrder::tr("Date: %1").arg(q(toIsoUtc(now)).replace('T', ' ').replace('Z', " UTC"));
  QString where = q(s.area);
  if (!s.water_type.empty()) where += (where.isEmpty() ? "" : ", ") + q(s.water_type);
  if (!s.payload_note.empty() || !where.isEmpty()) {
    h << WorkOrder::tr("Payload: %1; area: %2").arg(q(s.payload_note), where.isEmpty() ? WorkOrder::tr("not given") : where);
  }
  return h;
}

QStringList tableColumns() {
  return {WorkOrder::tr("Point"), WorkOrder::tr("Now"),   WorkOrder::tr("Change"),
          WorkOrder::tr("Pieces"), WorkOrder::tr("After"), WorkOrder::tr("Done")};
}

}  // namespace

std::vector<double> firstMissionInstalledKg(const WizardState& s, const FirstMissionReport& r) {
  if (r.method != "tank") return s.crane.installed_kg;
  std::vector<double> out;
  const auto& now = r.details.contains("ballast_now_g") ? r.details["ballast_now_g"] : nlohmann::json::object();
  for (const auto& p : s.vehicle->points) out.push_back(now.value(p.name, 0.0) / 1000.0);
  return out;
}

WorkOrder makeFirstMissionWorkOrder(const WizardState& s, TimePoint now) {
  if (!s.report || !s.vehicle) throw InputError("weighing", "nothing computed yet", "go back to the weighing page");
  const VehicleProfile& v = *s.vehicle;
  const FirstMissionReport& r = *s.report;
  const bool g = s.isGlider();
  // A glider's net buoyancy is a matter of grams (as on the result page).
  auto net = [g](double kg, bool sign) {
    return g ? WorkOrder::tr("%1 g").arg(sign ? signedFixed(kg * 1000.0, 1) : fixed(kg * 1000.0, 0))
             : WorkOrder::tr("%1 kg").arg(sign ? signedFixed(kg, 2) : fixed(kg, 1));
  };
  WorkOrder w;
  w.title = WorkOrder::tr("Ballast work order: first mission");
  w.header = headerLines(s, now);
  w.header << (r.method == "tank" ? WorkOrder::tr("From: the tank weighing") : WorkOrder::tr("From: the crane weighing"));
  w.water_title = WorkOrder::tr("Water the vehicle is balanced for");
  // A tank session states the target water by its density, not salinity.
  w.water << (r.method == "tank" ? WorkOrder::tr("Target water: density %1 kg/m³ at %2 °C")
                                       .arg(fixed(r.density_kgm3, 2))
                                       .arg(fixed(r.temperature_degC, 2))
                                 : WorkOrder::tr("%1 °C, %2 PSU at %3 m: density %4 kg/m³")
                                       .arg(fixed(r.temperature_degC, 2))
                                       .arg(fixed(r.salinity_psu, 2))
                                       .arg(fixed(r.depth_m, 0))
                                       .arg(fixed(r.density_kgm3, 2)))
          << WorkOrder::tr("Weighed %1 kg, buoyancy %2 kg: net buoyancy %3 before the change (positive = light)")
                 .arg(fixed(r.weight_kg, g ? 3 : 1), fixed(r.buoyancy_kg, g ? 3 : 1), net(r.net_buoyancy_kg, true));

  const std::vector<double> installed = firstMissionInstalledKg(s, r);
  w.columns = tableColumns();
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const PointRecommendation& p = r.points[i];
    const double before = i < installed.size() ? installed[i] : 0.0;
    w.rows.push_back({q(p.label), massText(before, g), massText(p.add_kg, g, true), piecesText(p, g),
                      massText(before + p.add_kg, g), QString()});
  }
  w.map = makeWeightMapModel(v, installed, r);

  const TrimSpec& spec = v.spec;
  const PredictedTrim& t = r.predicted;
  const bool nb_ok = t.net_buoyancy_kg >= spec.net_buoyancy_min_kg - 1e-9 && t.net_buoyancy_kg <= spec.net_buoyancy_max_kg + 1e-9;
  w.expected << WorkOrder::tr("After the change, in the water above:")
             << WorkOrder::tr("Net buoyancy %1 (band %2 .. %3): %4")
                    .arg(net(t.net_buoyancy_kg, true), net(spec.net_buoyancy_min_kg, false), net(spec.net_buoyancy_max_kg, false))
                    .arg(inBand(nb_ok))
             << WorkOrder::tr("Pitch at rest %1° (band ±%2°): %3")
                    .arg(signedFixed(t.pitch_deg, 2), fixed(spec.pitch_tolerance_deg, 1))
                    .arg(inBand(std::abs(t.pitch_deg) <= spec.pitch_tolerance_deg))
             << WorkOrder::tr("Roll %1° (band ±%2°): %3")
                    .arg(signedFixed(t.roll_deg, 2), fixed(spec.roll_tolerance_deg, 1))
                    .arg(inBand(std::abs(t.roll_deg) <= spec.roll_tolerance_deg));
  for (const auto& x : r.warnings) w.warnings << withPointLabels(adviceText(x), v);
  for (const auto& x : r.notes) w.notes << withPointLabels(adviceText(x), v);
  w.signature = WorkOrder::tr("Done by: ______________________   Signature: ______________________   Date: ____________");
  return w;
}

WorkOrder makeWorkOrder(const WizardState& s, const PlanBasis& basis, TimePoint now) {
  if (!s.plan || !s.vehicle) throw InputError("plan", "nothing planned yet", "go back to the pre-mission page");
  const VehicleProfile& v = *s.vehicle;
  const PreMissionPlan& p = *s.plan;
  const bool g = s.isGlider();
  const int nd = g ? 3 : 2;
  WorkOrder w;
  w.title = WorkOrder::tr("Ballast work order");
  w.header = headerLines(s, now);
  w.water_title = WorkOrder::tr("Next mission's water");
  w.header << WorkOrder::tr("Plan: %1 policy, from %2").arg(q(toString(p.policy)), q(basis.analysis_name));

  const PlannedPointResult& op = p.at_points.front();
  w.water << WorkOrder::tr("Operating depth %1 m: %2 °C, %3 PSU, in-situ density %4 kg/m³ (%5)")
                 .arg(fixed(op.water.depth_m, 0))
                 .arg(fixed(op.water.temperature_degC, 2))
                 .arg(fixed(op.water.salinity_psu, 2))
                 .arg(fixed(op.state.density_kgm3, 2))
                 .arg(s.next_water_source == "operator" ? WorkOrder::tr("entered by the operator") : WorkOrder::tr("last mission's CTD"));
  QStringList others;
  for (std::size_t i = 1; i < p.at_points.size(); ++i) {
    others << WorkOrder::tr("%1 m (%2)").arg(fixed(p.at_points[i].water.depth_m, 0)).arg(q(p.at_points[i].role));
  }
  if (!others.isEmpty()) w.water << WorkOrder::tr("Must also stay light at: %1").arg(others.join(", "));

  const std::vector<double> planned = installedAfterPlan(basis.installed_kg, p);
  const std::vector<double>& actual = s.actually_installed_kg.size() == planned.size() ? s.actually_installed_kg : planned;
  w.columns = tableColumns();
  bool differs = false;
  for (std::size_t i = 0; i < v.points.size() && i < p.points.size(); ++i) {
    const bool d = std::abs(actual[i] - planned[i]) > 5e-5;
    differs = differs || d;
    QString after = massText(actual[i], g);
    if (d) after += WorkOrder::tr(" (plan %1)").arg(massText(planned[i], g));
    w.rows.push_back({q(v.points[i].label), massText(i < basis.installed_kg.size() ? basis.installed_kg[i] : 0.0, g),
                      massText(p.points[i].add_kg, g, true), piecesText(p.points[i], g), after, QString()});
  }

  w.map = makeWeightMapModel(v, basis.installed_kg, p.points);

  const InstalledPrediction r = predictInstalled(v, p, basis.installed_kg, actual);
  const TrimSpec& spec = v.spec;
  // A quantity the analysis did not identify is "not known", never ± 0.
  const bool pitch_known = EstimateText::pitchKnown(p), roll_known = EstimateText::rollKnown(p);
  w.expected << (differs ? WorkOrder::tr("As actually installed, at %1 m:") : WorkOrder::tr("As planned, at %1 m:")).arg(fixed(op.water.depth_m, 0))
             << WorkOrder::tr("Net buoyancy %1 ± %2 kg (band %3 .. %4 kg): %5")
                    .arg(signedFixed(r.net_buoyancy_kg, nd), fixed(r.net_sigma_kg, nd))
                    .arg(fixed(std::max(0.0, spec.net_buoyancy_min_kg), 1), fixed(spec.net_buoyancy_max_kg, 1))
                    .arg(inBand(r.buoyancy_in_band))
             << WorkOrder::tr("Pitch at rest %1 (band ±%2°)%3")
                    .arg(EstimateText::valueSigma(pitch_known, r.pitch_deg, r.pitch_sigma_deg, 2, QStringLiteral("°")),
                         fixed(spec.pitch_tolerance_deg, 1), pitch_known ? ": " + inBand(r.pitch_in_band) : QString())
             << (r.flight_pitch_deg ? WorkOrder::tr("Pitch in flight at %1 m/s %2° (band ±%3°): %4")
                                            .arg(fixed(p.flight_speed_mps, 1), signedFixed(*r.flight_pitch_deg, 2),
                                                 fixed(spec.pitch_tolerance_deg, 1))
                                            .arg(inBand(r.flight_pitch_in_band.value_or(false)))
                                      : WorkOrder::tr("Pitch in flight: not predicted (no hydrodynamics or cruise speed)"))
             << WorkOrder::tr("Roll %1 (band ±%2°)%3")
                    .arg(EstimateText::valueSigma(roll_known, r.roll_deg, r.roll_sigma_deg, 2, QStringLiteral("°")),
                         fixed(spec.roll_tolerance_deg, 1), roll_known ? ": " + inBand(r.roll_in_band) : QString())
             << (r.safe ? WorkOrder::tr("Safe: at least %1 kg light (1.645 σ) at every planned depth.")
                        : WorkOrder::tr("NOT SAFE: less than %1 kg light (1.645 σ) at a planned depth."))
                    .arg(fixed(p.margin_kg, nd));
  for (const auto& x : p.warnings) w.warnings << adviceText(x);
  if (basis.from_session) w.header << EstimateText::planUses(basis.source);
  if (basis.report.is_object())
    w.calibration = CalibrationTable::lines(CalibrationTable::rowsFromJson(basis.report.value("calibration", nlohmann::json::array())));
  if (p.calibration_manoeuvre) w.manoeuvre = CalibrationTable::manoeuvreLines(*p.calibration_manoeuvre);
  if (const QString after = CalibrationTable::afterMoveLine(p.after_move_net_sigma_kg, p.after_move_x_sigma_m); !after.isEmpty())
    w.manoeuvre << after;
  w.signature = WorkOrder::tr("Done by: ______________________   Signature: ______________________   Date: ____________");
  return w;
}

void drawWorkOrder(QPainter& painter, const QPaintDevice& device, const WorkOrder& w) {
  const double mm = device.logicalDpiX() / 25.4;
  const QRectF page(15 * mm, 15 * mm, device.width() - 30 * mm, device.height() - 30 * mm);
  painter.save();
  painter.fillRect(QRectF(0, 0, device.width(), device.height()), Qt::white);
  painter.setPen(Qt::black);
  // The fonts are named, never left to the desktop: DejaVu Sans (Debian's
  // fonts-dejavu-core and -extra) prints the same page on every machine.
  QFont body(QStringLiteral("DejaVu Sans"));
  body.setPointSizeF(9.5);
  QFont bold = body;
  bold.setBold(true);
  QFont title = bold;
  title.setPointSizeF(16);
  QFont section = bold;
  section.setPointSizeF(11);
  QFont small = body;
  small.setPointSizeF(8.5);
  double y = page.top();
  // Draws `t` at y and moves y below it; with draw = false only measures.
  auto text = [&](const QString& t, const QFont& f, double gap_mm = 1.0, bool draw = true) {
    painter.setFont(f);
    const QRectF box(page.left(), y, page.width(), std::max(page.bottom() - y, 10 * mm));
    const QRectF used = painter.boundingRect(box, Qt::TextWordWrap, t);
    if (draw) painter.drawText(box, Qt::TextWordWrap, t);
    y += used.height() + gap_mm * mm;
  };
  auto rule = [&] {
    painter.setPen(QPen(Qt::black, 0.3 * mm));
    painter.drawLine(QPointF(page.left(), y), QPointF(page.right(), y));
    painter.setPen(Qt::black);
    y += 2 * mm;
  };
  // Everything below the map: expected result, warnings, notes.
  // The tail's fonts: smaller when it would not fit above the signature.
  QFont t_body = body, t_section = section, t_small = small;
  auto tail = [&](bool draw) {
    text(WorkOrder::tr("Expected result"), t_section, 1.0, draw);
    for (const auto& e : w.expected) text(e, t_body, 0.5, draw);
    if (!w.warnings.isEmpty()) {
      y += 2 * mm;
      text(WorkOrder::tr("Warnings"), t_section, 1.0, draw);
      for (const auto& x2 : w.warnings) text(WorkOrder::tr("⚠ %1").arg(x2), t_body, 0.5, draw);
    }
    if (!w.calibration.isEmpty()) {
      y += 2 * mm;
      text(WorkOrder::tr("What was calibrated"), t_section, 1.0, draw);
      for (const auto& c : w.calibration) text(QStringLiteral("• %1").arg(c), t_small, 0.3, draw);
    }
    if (!w.manoeuvre.isEmpty()) {
      y += 2 * mm;
      text(WorkOrder::tr("Calibration manoeuvre for the next mission"), t_section, 1.0, draw);
      for (const auto& m : w.manoeuvre) text(QStringLiteral("• %1").arg(m), t_small, 0.3, draw);
    }
    if (!w.notes.isEmpty()) {
      y += 2 * mm;
      text(WorkOrder::tr("Steps and notes"), t_section, 1.0, draw);
      for (const auto& n : w.notes) text(QStringLiteral("• %1").arg(n), t_small, 0.3, draw);
    }
  };

  text(w.title, title, 2);
  for (const auto& h : w.header) text(h, body, 0.5);
  y += 2 * mm;
  rule();
  text(w.water_title, section);
  for (const auto& l : w.water) text(l, body, 0.5);
  y += 3 * mm;
  text(WorkOrder::tr("What to change"), section);

  // The table: fixed column shares of the width; the pieces column wraps.
  const double shares[6] = {0.19, 0.10, 0.10, 0.37, 0.16, 0.08};
  std::vector<double> x{page.left()};
  for (double s : shares) x.push_back(x.back() + s * page.width());
  const double pad = 1.5 * mm;
  auto rowHeight = [&](const QStringList& cells, const QFont& f) {
    painter.setFont(f);
    double h = 0;
    for (int c = 0; c < cells.size() && c < 6; ++c) {
      const QRectF cell(x[c] + pad, 0, x[c + 1] - x[c] - 2 * pad, 1000 * mm);
      h = std::max(h, painter.boundingRect(cell, Qt::TextWordWrap, cells[c]).height());
    }
    return h + 2 * pad;
  };
  auto drawRow = [&](const QStringList& cells, const QFont& f, bool header) {
    const double h = std::max(rowHeight(cells, f), 8.0 * mm);
    if (header) painter.fillRect(QRectF(page.left(), y, page.width(), h), QColor(225, 230, 236));
    painter.setPen(QPen(Qt::black, 0.2 * mm));
    painter.drawRect(QRectF(page.left(), y, page.width(), h));
    for (int c = 1; c < 6; ++c) painter.drawLine(QPointF(x[c], y), QPointF(x[c], y + h));
    painter.setPen(Qt::black);
    painter.setFont(f);
    for (int c = 0; c < cells.size() && c < 6; ++c) {
      const QRectF cell(x[c] + pad, y + pad, x[c + 1] - x[c] - 2 * pad, h - 2 * pad);
      painter.drawText(cell, Qt::TextWordWrap | Qt::AlignVCenter, cells[c]);
    }
    if (!header) {  // an empty box to tick by hand
      const double b = 4 * mm;
      painter.drawRect(QRectF((x[5] + x[6] - b) / 2, y + (h - b) / 2, b, b));
    }
    y += h;
  };
  drawRow(w.columns, bold, true);
  for (const auto& r : w.rows) drawRow(r, body, false);
  y += 4 * mm;

  if (w.map.length_m > 0) {
    // The map takes what the text below leaves of the page (30..65 mm).
    const double map_top = y;
    // The signature line must stay on the page (a long tail pushed it off
    // the demo's order): the tail's fonts shrink in steps, at most to 75 %.
    double tail_h = 0.0;
    for (double f = 1.0; f > 0.74; f -= 0.05) {
      t_body.setPointSizeF(body.pointSizeF() * f);
      t_section.setPointSizeF(section.pointSizeF() * f);
      t_small.setPointSizeF(small.pointSizeF() * f);
      y = map_top;
      tail(false);
      tail_h = y - map_top;
      // The map's title, the smallest map, the tail, then the signature's
      // gap, rule and line (drawn from y + 8 mm).
      const double need = 8 * mm + 30 * mm + 3 * mm + tail_h + 16 * mm;
      if (map_top + need <= page.bottom()) break;
    }
    y = map_top;
    text(WorkOrder::tr("Where (top view, bow to the right)"), section);
    const double free_h = page.bottom() - 30 * mm - y - tail_h;
    const double map_h = std::clamp(free_h, 30 * mm, 65 * mm);
    // drawWeightMap works in 96 dpi pixels: scale the painter to the
    // device and size the font so it prints at 8 pt after scaling.
    const double k = device.logicalDpiX() / 96.0;
    QFont map_font = body;
    map_font.setPointSizeF(8.0 / k);
    painter.save();
    painter.translate(page.left(), y);
    painter.scale(k, k);
    drawWeightMap(painter, QRectF(0, 0, page.width() / k, map_h / k), w.map, {map_font, Qt::white, Qt::black});
    painter.restore();
    y += map_h + 3 * mm;
  }
  tail(true);
  // The signature line at the foot of the page.
  y = std::max(y + 8 * mm, page.bottom() - 20 * mm);
  rule();
  text(w.signature, body);
  painter.restore();
}

QString writeWorkOrderPdf(const WorkOrder& w, const QString& path) {
  QPdfWriter pdf(path);
  pdf.setPageSize(QPageSize(QPageSize::A4));
  pdf.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
  pdf.setResolution(300);
  pdf.setTitle(w.title);
  pdf.setCreator(QStringLiteral("auvballast"));
  {
    QPainter painter;
    if (!painter.begin(&pdf)) return WorkOrder::tr("cannot write %1: check the folder and its permissions").arg(path);
    drawWorkOrder(painter, pdf, w);
  }
  const QFileInfo info(path);
  if (!info.exists() || info.size() == 0) return WorkOrder::tr("cannot write %1: check the folder and its permissions").arg(path);
  return {};
}

QImage renderWorkOrder(const WorkOrder& w, int dpi) {
  const double px_per_mm = dpi / 25.4;
  QImage img(static_cast<int>(std::round(210 * px_per_mm)), static_cast<int>(std::round(297 * px_per_mm)),
             QImage::Format_RGB32);
  const int dpm = static_cast<int>(std::round(dpi / 0.0254));
  img.setDotsPerMeterX(dpm);
  img.setDotsPerMeterY(dpm);
  img.fill(Qt::white);
  QPainter painter(&img);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setRenderHint(QPainter::TextAntialiasing);
  drawWorkOrder(painter, img, w);
  return img;
}

QString writePreMissionJson(const WizardState& s, const PlanBasis& basis, TimePoint now, const QString& path) {
  try {
    const nlohmann::json j = preMissionReportJson(s, basis, toIsoUtc(now));
    std::ofstream out(path.toStdString(), std::ios::trunc);
    out << j.dump(2) << "\n";
    out.flush();
    if (!out) return WorkOrder::tr("cannot write %1: check the folder and its permissions").arg(path);
  } catch (const InputError& e) {
    return q(e.what());
  }
  return {};
}

}  // namespace auv::ui
