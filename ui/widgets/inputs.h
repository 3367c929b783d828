#pragma once
// The input widgets every page uses, built the same way: an object name for
// tests, the unit beside the field, a tooltip saying what to measure and how, and
// a 32 px minimum height for gloved hands on a dockside laptop.
#include <QFrame>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QString>
#include <algorithm>
#include <cmath>

#include "widgets/number_input.h"

namespace auv::ui {

// Messages that may outgrow their space: a word-wrapped, selectable label
// (object name `name`, returned in *label) in a frameless scroll area.
inline QScrollArea* makeMessageArea(const QString& name, QLabel** label, Qt::TextFormat format = Qt::AutoText) {
  auto* l = new QLabel;
  l->setObjectName(name);
  l->setWordWrap(true);
  l->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  l->setTextFormat(format);
  l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* scroll = new QScrollArea;
  scroll->setWidget(l);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  *label = l;
  return scroll;
}

// Every numeric field: widgets/number_input.h (typed text is never rewritten
// while typing; the unit is a label beside the field).
inline NumberInput* makeNumber(const QString& name, double lo, double hi, int decimals, const QString& unit,
                               const QString& tip) {
  auto* s = new NumberInput(unit);
  s->setObjectName(name);
  s->setDecimals(decimals);
  s->setRange(lo, hi);
  s->setToolTip(tip);
  s->setMinimumHeight(32);
  return s;
}

// A red label next to the fields for the message of an InputError.
inline QLabel* makeErrorLabel(const QString& name = QStringLiteral("error")) {
  auto* l = new QLabel;
  l->setObjectName(name);
  l->setWordWrap(true);
  l->setStyleSheet("color: #b00020;");
  return l;
}

// Numbers on pages in the wizard's language (translations.h sets the
// default locale with the translation: "1025,4" under --lang nb), without
// group separators (a technician types 1565.2, not 1,565.2). Files a
// program reads (CSV export) keep '.'.
inline QLocale displayLocale() {
  QLocale l;
  l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
  return l;
}

// A number with fixed decimals that never shows "-0.00".
inline QString fixed(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  if (std::round(v * scale) == 0.0) v = 0.0;
  return displayLocale().toString(v, 'f', decimals);
}

// Significant digits ('g'), for fitted constants of any size.
inline QString significant(double v, int digits) { return displayLocale().toString(v, 'g', digits); }

// The same with a "+" on positive values (net buoyancy, attitudes).
inline QString signedFixed(double v, int decimals) {
  const bool positive = std::round(v * std::pow(10.0, decimals)) > 0.0;
  return (positive ? QStringLiteral("+") : QString()) + fixed(v, decimals);
}

// Glider ballast is set to the gram, AUV kit pieces are kilograms: show
// each in the unit the technician works in.
// Kilograms get the decimals the value needs, 1 to 3: Delphin2's 0.05 kg
// piece must not read "0.1 kg", nor 24.05 kg typed by the operator "24.1".
inline QString massText(double kg, bool grams, bool sign = false) {
  // Round first so that -0.4 g reads "0 g", not "-0 g".
  int decimals = 1;
  while (!grams && decimals < 3) {
    const double scaled = kg * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, std::abs(scaled))) break;
    ++decimals;
  }
  const double unit = std::pow(10.0, decimals);
  const double shown = grams ? std::round(kg * 1000.0) : std::round(kg * unit) / unit;
  const double v = shown == 0.0 ? 0.0 : shown;
  const QString plus = sign && v > 0 ? QStringLiteral("+") : QString();
  if (grams) return QStringLiteral("%1%2 g").arg(plus, fixed(v, 0));
  return QStringLiteral("%1%2 kg").arg(plus, fixed(v, decimals));
}

}  // namespace auv::ui
