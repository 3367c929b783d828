#pragma once
// The one numeric field of the wizard. A technician types a reading key by
// key; nothing may rewrite the text while they type (NumberInput with
// keyboard tracking did: "391." became "391.0" and the "7" was refused).
//  - the text is free while typing; it is read (committed) when editing
//    finishes (Tab, Enter, focus leaves) and only then valueChanged() fires;
//  - while typing, a red frame and tooltip say when the text is not a number
//    or is out of range (the only live reaction);
//  - both '.' and ',' are taken as the decimal separator and the committed
//    value is shown in the user's locale (nb: "1025,4");
//  - the unit is a label beside the field, never part of the text;
//  - focus-in selects everything, so typing replaces the old value; a click
//    that places the cursor afterwards lets the technician edit in place;
//  - a committed value keeps every digit typed (display decimals grow to
//    show it): 0.0855 in a 3-decimal field stays 0.0855.
#include <QLineEdit>
#include <QString>
#include <QWidget>

class QLabel;

namespace auv::ui {

class NumberEdit : public QLineEdit {
  Q_OBJECT
 public:
  using QLineEdit::QLineEdit;

 signals:
  void stepRequested(int steps);  // Up / Down arrow

 protected:
  void focusInEvent(QFocusEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;

 private:
  bool select_on_release_ = false;
};

class NumberInput : public QWidget {
  Q_OBJECT
 public:
  explicit NumberInput(const QString& unit = QString(), QWidget* parent = nullptr);

  // The value in the field: the text being typed when it is a number in
  // range (so a store or autosave mid-typing keeps it), else the last
  // committed value.
  double value() const;
  // Shows v with the field's decimals (more if v needs them); emits
  // valueChanged when the value changes.
  void setValue(double v);
  void setRange(double lo, double hi);
  void setMinimum(double lo) { setRange(lo, max_); }
  void setMaximum(double hi) { setRange(min_, hi); }
  double minimum() const { return min_; }
  double maximum() const { return max_; }
  void setDecimals(int d);
  int decimals() const { return decimals_; }
  void setSingleStep(double s) { step_ = s; }
  // An optional field: the minimum means "not given" and shows as an empty
  // field with this text greyed in it; clearing the field gives the minimum.
  void setSpecialValueText(const QString& text);
  QString unit() const;
  void setUnit(const QString& unit);

  // The text in the field as typed (not yet committed while editing).
  QString text() const;
  // Where keys go: the focus proxy (tests type into it as a person would).
  QLineEdit* lineEdit() const { return edit_; }
  // False while the text is not a number in range; problem() says why.
  bool hasAcceptableInput() const { return problem_.isEmpty(); }
  QString problem() const { return problem_; }
  // Reads the text now (as focus-out does). Returns hasAcceptableInput().
  bool commit();

  // The text of a number as this field shows it (locale decimal separator).
  QString format(double v) const;
  // A typed number: '.' or ',' as decimal separator, no grouping.
  static bool parse(const QString& text, double* out);

 signals:
  void valueChanged(double value);
  // Every keystroke (for hints only; value() is unchanged until commit).
  void textEdited(const QString& text);

 protected:
  void changeEvent(QEvent* e) override;

 private:
  void checkLive();
  void updateMinimumWidth();
  void showProblem();
  void stepBy(int steps);

  NumberEdit* edit_;
  QLabel* unit_;
  double value_ = 0.0;
  double min_ = 0.0, max_ = 99.99;
  double step_ = 1.0;
  int decimals_ = 2;
  QString problem_;
  QString special_;
};

}  // namespace auv::ui
