#include "widgets/number_input.h"

#include <QApplication>
#include <QEvent>
#include <QFocusEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "widgets/inputs.h"

namespace auv::ui {

void NumberEdit::keyPressEvent(QKeyEvent* e) {
  select_on_release_ = false;
  if (e->key() == Qt::Key_Up || e->key() == Qt::Key_Down) {
    emit stepRequested(e->key() == Qt::Key_Up ? 1 : -1);
    e->accept();
    return;
  }
  QLineEdit::keyPressEvent(e);
}

void NumberEdit::focusInEvent(QFocusEvent* e) {
  QLineEdit::focusInEvent(e);
  // The whole value is selected, so the first key typed replaces it; after a
  // click again once the mouse is released (the press placed the cursor).
  // The focus reason is not trusted to tell a click (synthetic clicks come
  // with other reasons): the next release selects unless a key came first.
  selectAll();
  select_on_release_ = true;
}

void NumberEdit::mouseReleaseEvent(QMouseEvent* e) {
  QLineEdit::mouseReleaseEvent(e);
  // A drag that selected part of the text keeps that selection.
  if (select_on_release_ && !hasSelectedText()) selectAll();
  select_on_release_ = false;
}

NumberInput::NumberInput(const QString& unit, QWidget* parent) : QWidget(parent) {
  edit_ = new NumberEdit;
  edit_->setObjectName("number");
  edit_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  edit_->setMinimumHeight(32);
  unit_ = new QLabel(unit.trimmed());
  unit_->setObjectName("unit");
  unit_->setVisible(!unit.trimmed().isEmpty());
  auto* lay = new QHBoxLayout(this);
  lay->setContentsMargins(0, 0, 0, 0);
  lay->setSpacing(6);
  lay->addWidget(edit_, 1);
  lay->addWidget(unit_);
  setFocusProxy(edit_);
  setFocusPolicy(Qt::StrongFocus);
  edit_->setText(format(value_));
  connect(edit_, &QLineEdit::textEdited, this, [this](const QString& t) {
    checkLive();
    emit textEdited(t);
  });
  connect(edit_, &QLineEdit::editingFinished, this, [this] { commit(); });
  connect(edit_, &NumberEdit::stepRequested, this, [this](int steps) { stepBy(steps); });
}

QString NumberInput::unit() const { return unit_->text(); }

void NumberInput::setUnit(const QString& unit) {
  unit_->setText(unit.trimmed());
  unit_->setVisible(!unit.trimmed().isEmpty());
}

QString NumberInput::text() const { return edit_->text(); }

void NumberInput::setSpecialValueText(const QString& text) {
  special_ = text;
  edit_->setPlaceholderText(text);
  edit_->setText(format(value_));
}

QString NumberInput::format(double v) const {
  if (!special_.isEmpty() && v == min_) return QString();
  // As many decimals as the value needs (up to six more than the field's),
  // so a committed value is shown as typed.
  int d = decimals_;
  const double tol = 1e-9 * std::max(1.0, std::abs(v));
  while (d < decimals_ + 6 && std::abs(std::round(v * std::pow(10.0, d)) / std::pow(10.0, d) - v) > tol) ++d;
  return fixed(v, d);  // the pages' locale, never "-0.0"
}

bool NumberInput::parse(const QString& text, double* out) {
  QString t = text.trimmed();
  t.remove(QChar(' ')).remove(QChar(0x00A0)).remove(QChar(0x202F));
  t.replace(QChar(','), QChar('.'));
  t.replace(QChar(0x2212), QChar('-'));  // typographic minus
  if (t.startsWith('+')) t.remove(0, 1);
  if (t.isEmpty() || t.count('.') > 1) return false;
  for (QChar c : t)
    if (!(c.isDigit() || c == '.' || c == '-' || c == 'e' || c == 'E')) return false;
  const std::string s = t.toStdString();
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

double NumberInput::value() const {
  const QString t = edit_->text();
  if (t.trimmed().isEmpty()) return special_.isEmpty() ? value_ : min_;
  double v = 0.0;
  if (parse(t, &v) && v >= min_ && v <= max_) return v;
  return value_;
}

void NumberInput::setValue(double v) {
  v = std::clamp(v, min_, max_);
  const bool changed = v != value_;
  value_ = v;
  edit_->setText(format(v));
  problem_.clear();
  showProblem();
  if (changed) emit valueChanged(value_);
}

void NumberInput::setRange(double lo, double hi) {
  min_ = lo;
  max_ = std::max(lo, hi);
  if (value_ < min_ || value_ > max_) setValue(value_);
  updateMinimumWidth();
}

void NumberInput::setDecimals(int d) {
  decimals_ = std::max(0, d);
  edit_->setText(format(value_));
  updateMinimumWidth();
}

// Wide enough for the longest value of the range with the field's decimals
// (and a sign), so a long label beside it cannot squeeze the number out of
// sight (Delphin2's installed masses read "l.00" on the adjustment page).
void NumberInput::updateMinimumWidth() {
  const double widest = std::min(std::max(std::abs(min_), std::abs(max_)), 99999.0);
  const int digits = 1 + static_cast<int>(std::floor(std::log10(std::max(1.0, widest))));
  const int chars = digits + (decimals_ > 0 ? decimals_ + 1 : 0) + (min_ < 0.0 ? 1 : 0);
  const QMargins m = edit_->textMargins();
  edit_->setMinimumWidth(edit_->fontMetrics().horizontalAdvance(QString(chars, QLatin1Char('0'))) + m.left() +
                         m.right() + 18);
}

void NumberInput::checkLive() {
  double v = 0.0;
  const QString t = edit_->text();
  if (t.trimmed().isEmpty() && !special_.isEmpty()) {
    problem_.clear();
  } else if (t.trimmed().isEmpty() || t.trimmed() == "-" || t.trimmed() == "+") {
    problem_ = tr("Enter a number.");
  } else if (!parse(t, &v)) {
    problem_ = tr("'%1' is not a number.").arg(t);
  } else if (v < min_) {
    problem_ = tr("The lowest accepted value is %1 %2.").arg(format(min_), unit());
  } else if (v > max_) {
    problem_ = tr("The highest accepted value is %1 %2.").arg(format(max_), unit());
  } else {
    problem_.clear();
  }
  showProblem();
}

void NumberInput::showProblem() {
  if (problem_.isEmpty()) {
    edit_->setStyleSheet(QString());
    edit_->setToolTip(QString());
  } else {
    edit_->setStyleSheet("QLineEdit { border: 2px solid #b00020; background: #fdecee; }");
    edit_->setToolTip(problem_);
  }
}

bool NumberInput::commit() {
  checkLive();
  if (!problem_.isEmpty()) return false;
  double v = min_;
  if (!(edit_->text().trimmed().isEmpty() && !special_.isEmpty())) parse(edit_->text(), &v);
  const bool changed = v != value_;
  value_ = v;
  // The typed digits stay; only the separator follows the locale and
  // the field's decimals are filled ("5." -> "5.00", "391,7" -> "391.7" in en).
  edit_->setText(format(v));
  if (changed) emit valueChanged(value_);
  return true;
}

void NumberInput::stepBy(int steps) {
  if (!commit()) return;
  setValue(value_ + steps * step_);
  edit_->selectAll();
}

void NumberInput::changeEvent(QEvent* e) {
  QWidget::changeEvent(e);
  if (e->type() == QEvent::LocaleChange && problem_.isEmpty()) edit_->setText(format(value_));
}

}  // namespace auv::ui
