#include "widgets/calibration_table.h"

#include <QHeaderView>
#include <algorithm>
#include <cmath>
#include <map>

#include "widgets/inputs.h"

namespace auv::ui {
namespace {

// Constants span 1e-5 (a torque per rpm²) to thousands: significant digits,
// never an exponent for a number with more integer digits than that.
QString sig(double v, int digits) {
  if (std::abs(v) >= 1.0) digits = std::max(digits, static_cast<int>(std::floor(std::log10(std::abs(v)))) + 1);
  return significant(v, digits);
}

// The unit as a technician reads it; BG is reported in m and shown in mm.
struct Shown {
  double scale = 1.0;
  QString unit;
  bool relative = false;  // a multiple of the profile's value: the profile's is 1
};
Shown shownUnit(const std::string& id, const std::string& unit) {
  if (unit == "m") return {1000.0, CalibrationTable::tr(" mm")};
  if (unit == "1" || unit == "x profile") return {1.0, QString(), true};
  if (unit == "nondimensional" || unit.empty()) return {1.0, QString()};
  if (unit == "deg") return {1.0, QStringLiteral("°")};
  if (unit == "N*m/rpm^2") return {1.0, QStringLiteral(" N·m/rpm²")};
  if (unit == "N m s2/m2") return {1.0, QStringLiteral(" N·s²")};
  (void)id;
  QString u = QString::fromStdString(unit);
  return {1.0, " " + u.replace('*', QChar(0x00B7)).replace("^2", QStringLiteral("²"))};
}

CalibrationRow makeRow(const std::string& id, const std::string& unit, double value, double sigma, double profile,
                       bool identified, bool from_analysis, bool used = true) {
  Shown s = shownUnit(id, unit);
  // A unit that is a sentence ("N m at 100 rpm, bollard (J = 0)") would take
  // the table's width: it goes to the row's tooltip.
  QString unit_note;
  if (s.unit.size() > 12) {
    unit_note = CalibrationTable::tr("Unit: %1").arg(s.unit.trimmed());
    s.unit.clear();
  }
  CalibrationRow r;
  r.name = CalibrationTable::nameOf(id);
  r.value = std::isfinite(value) && std::isfinite(sigma) && sigma > 0.0
                ? CalibrationTable::tr("%1 ± %2%3").arg(sig(value * s.scale, 3), sig(sigma * s.scale, 2), s.unit)
                : CalibrationTable::tr("not known");
  // The profile's value in the value's unit (said once, beside the value).
  r.profile = !std::isfinite(profile) ? CalibrationTable::tr("not given")
              : s.relative             ? CalibrationTable::tr("%1 = profile").arg(sig(profile, 3))
                                       : sig(profile * s.scale, 3);
  r.identified = identified;
  r.from_analysis = from_analysis;
  r.used = used;
  r.unit_note = unit_note;
  return r;
}

double num(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : NAN;
}

}  // namespace

CalibrationTable::CalibrationTable(QWidget* parent) : QTableWidget(0, 4, parent) {
  setObjectName("calibration");
  setHorizontalHeaderLabels({tr("Calibrated constant"), tr("Value ± σ"), tr("Profile"), tr("From")});
  verticalHeader()->hide();
  verticalHeader()->setDefaultSectionSize(22);
  // The name takes what the numbers leave (elided; the tooltip has it whole).
  horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  setTextElideMode(Qt::ElideRight);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setEditTriggers(QAbstractItemView::NoEditTriggers);
  setSelectionMode(QAbstractItemView::NoSelection);
  setFocusPolicy(Qt::NoFocus);  // read only: Tab goes on to the next field
  setToolTip(tr("The vehicle constants fitted together with the ballast state. \"This log\": the log narrowed "
                "it; \"stayed at the prior\": the log could not tell, the profile's value and its uncertainty stand; "
                "\"the analysis, held\": the model check kept the same log's analysis's value and σ; \"profile's kept\": the log "
                "measured it and found no significant change, so the estimate kept the "
                "profile's value."));
}

void CalibrationTable::showRows(const std::vector<CalibrationRow>& rows) {
  setRowCount(0);
  clearSpans();
  if (rows.empty()) {
    setRowCount(1);
    setItem(0, 0, new QTableWidgetItem(tr("Nothing was calibrated: the profile's constants are used as they are.")));
    setSpan(0, 0, 1, 4);
    return;
  }
  for (const auto& r : rows) {
    const int i = rowCount();
    insertRow(i);
    auto* name = new QTableWidgetItem(r.name);
    name->setToolTip(r.unit_note.isEmpty() ? r.name : r.name + "\n" + r.unit_note);
    setItem(i, 0, name);
    auto* value = new QTableWidgetItem(r.value);
    value->setToolTip(r.unit_note);
    setItem(i, 1, value);
    setItem(i, 2, new QTableWidgetItem(r.profile));
    setItem(i, 3, new QTableWidgetItem(source(r)));
  }
}

std::vector<CalibrationRow> CalibrationTable::rowsFromJson(const nlohmann::json& list) {
  std::vector<CalibrationRow> out;
  if (!list.is_array()) return out;
  for (const auto& c : list) {
    if (!c.is_object() || !c.contains("id") || !c["id"].is_string()) continue;
    out.push_back(makeRow(c["id"].get<std::string>(), c.value("unit", std::string()), num(c, "value"), num(c, "sigma"),
                      num(c, "profile_value"), c.value("identified", false),
                          c.value("from_analysis", false), c.value("used", true)));
  }
  return out;
}

std::vector<CalibrationRow> CalibrationTable::rowsOf(const std::vector<discrepancy::CalibrationValue>& list) {
  std::vector<CalibrationRow> out;
  for (const auto& c : list) out.push_back(makeRow(c.id, c.unit, c.value, c.sigma, c.profile_value, c.identified, c.from_analysis));
  return out;
}

QString CalibrationTable::nameOf(const std::string& id) {
  static const std::map<std::string, const char*> names = {
      {"heave_lift_scale", QT_TR_NOOP("Heave lift of the hull")},
      {"heave_derivatives", QT_TR_NOOP("Heave force derivatives")},
      {"pitch_moment_uw", QT_TR_NOOP("Pitch moment from heave (with the Munk moment)")},
      {"net_pitch_moment_derivative", QT_TR_NOOP("Pitch moment from heave (with the Munk moment)")},
      {"crossflow_scale", QT_TR_NOOP("Cross-flow lift and moment")},
      {"crossflow_pitch_moment", QT_TR_NOOP("Cross-flow pitch moment")},
      {"stern_plane_effectiveness", QT_TR_NOOP("Stern-plane effectiveness")},
      {"elevator_zero_offset", QT_TR_NOOP("Elevator zero offset")},
      {"bg", QT_TR_NOOP("BG (CG below CB)")},
      {"propeller_torque", QT_TR_NOOP("Propeller torque")},
      {"pitch_damping", QT_TR_NOOP("Pitch damping")},
      {"roll_damping", QT_TR_NOOP("Roll damping")},
      {"surge_drag", QT_TR_NOOP("Surge drag")},
      {"hull_compressibility", QT_TR_NOOP("Hull compressibility")},
      {"thermal_expansion", QT_TR_NOOP("Hull thermal expansion")},
      {"mass_drift", QT_TR_NOOP("Mass drift")},
  };
  if (const auto it = names.find(id); it != names.end()) return tr(it->second);
  // A constant this program has no name for yet: its id as words.
  QString words = QString::fromStdString(id).replace('_', ' ');
  if (!words.isEmpty()) words[0] = words[0].toUpper();
  return words;
}

QString CalibrationTable::source(const CalibrationRow& r) {
  if (r.from_analysis) return tr("the analysis, held");
  if (r.identified && !r.used) return tr("profile's kept");
  return r.identified ? tr("this log") : tr("stayed at the prior");
}

QStringList CalibrationTable::lines(const std::vector<CalibrationRow>& rows) {
  // What the log set, one line each; the constants left at the profile's
  // value in one line by name (a printed page has no room for ten lines
  // that each say "the profile's"; the table and the JSON report have them).
  QStringList out, kept;
  for (const auto& r : rows) {
    if (!r.from_analysis && (!r.identified || !r.used)) {
      kept << r.name;
      continue;
    }
    out << tr("%1: %2 (profile %3); %4").arg(r.name, r.value, r.profile, source(r)) +
               (r.unit_note.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(r.unit_note));
  }
  if (!kept.isEmpty())
    out << tr("At the profile's value (the log could not tell, or agreed with it): %1").arg(kept.join(QStringLiteral(", ")));
  return out;
}

QStringList CalibrationTable::manoeuvreLines(const nlohmann::json& m) {
  QStringList out;
  if (!m.is_object() || !m.contains("legs") || !m["legs"].is_array() || m["legs"].empty()) return out;
  QStringList legs;
  for (const auto& leg : m["legs"])
    if (leg.is_string()) legs << QString::fromStdString(leg.get<std::string>());
  out << legs.join("; ");
  if (m.contains("expected_sigma") && m["expected_sigma"].is_object()) {
    const auto& e = m["expected_sigma"];
    QStringList parts;
    if (std::isfinite(num(e, "net_buoyancy_kg"))) parts << tr("net buoyancy ± %1 kg").arg(fixed(num(e, "net_buoyancy_kg"), 2));
    if (std::isfinite(num(e, "cg_x_mm"))) parts << tr("CG x ± %1 mm").arg(fixed(num(e, "cg_x_mm"), 1));
    if (!parts.isEmpty()) out << tr("Expected afterwards (1 σ): %1").arg(parts.join(", "));
  }
  return out;
}

QString CalibrationTable::afterMoveLine(std::optional<double> net_sigma_kg, std::optional<double> x_sigma_m) {
  if (!net_sigma_kg) return {};
  QString s = tr("net buoyancy ± %1 kg").arg(fixed(*net_sigma_kg, 2));
  if (x_sigma_m) s += ", " + tr("CG x ± %1 mm").arg(fixed(*x_sigma_m * 1e3, *x_sigma_m < 1e-4 ? 2 : 1));  // not "± 0.0"
  return tr("The move is also a calibration: flown after it and analysed with this log as history, the next "
            "mission's survey should give %1 (1 σ).")
      .arg(s);
}

}  // namespace auv::ui
