#pragma once
// Typing as a person does: click into a field, press one key per character,
// leave it with Tab. Used by every page's test so that each numeric field is
// driven through the keyboard, never through setValue().
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QTableWidget>
#include <QGroupBox>
#include <QLabel>
#include <QRegularExpression>
#include <QLineEdit>
#include <QLocale>
#include <QSet>
#include <QStringList>
#include <QWizard>
#include <QWizardPage>
#include <QtTest/QTest>
#include <cmath>

#include "widgets/number_input.h"

namespace auv::testing {

inline QWidget* focused() { return QApplication::focusWidget(); }

// Click into `in` as a person does (the field selects all on release).
inline void clickInto(ui::NumberInput* in) {
  QLineEdit* e = in->lineEdit();
  if (!in->window()->isActiveWindow()) {
    in->window()->activateWindow();
    if (!QTest::qWaitForWindowActive(in->window(), 200)) QApplication::setActiveWindow(in->window());
  }
  QTest::mouseClick(e, Qt::LeftButton, Qt::NoModifier, QPoint(e->width() - 4, e->height() / 2));
  if (focused() != e) {
    // Offscreen, a page change can leave no window active, and a click then
    // gives no focus; a person's click always does.
    QApplication::setActiveWindow(in->window());
    e->setFocus(Qt::MouseFocusReason);
    QTest::mouseClick(e, Qt::LeftButton, Qt::NoModifier, QPoint(e->width() - 4, e->height() / 2));
  }
}

// Click into `in` (the cursor lands where the click is, then the field
// selects all), type `text` key by key, checking after every key that the
// field shows exactly what was typed so far, then Tab away.
inline void typeInto(ui::NumberInput* in, const QString& text) {
  QLineEdit* e = in->lineEdit();
  // A person's window is the active one (offscreen, a page change or a
  // closed dialog may leave none active).
  if (!in->window()->isActiveWindow()) {
    in->window()->activateWindow();
    if (!QTest::qWaitForWindowActive(in->window(), 200)) QApplication::setActiveWindow(in->window());
  }
  QTest::mouseClick(e, Qt::LeftButton, Qt::NoModifier, QPoint(e->width() - 4, e->height() / 2));
  QApplication::processEvents();  // the focus-in selection runs in the next event cycle
  if (focused() != e) {
    // Offscreen, a page change can leave no window active, and a click then
    // gives no focus; a person's click always does.
    QApplication::setActiveWindow(in->window());
    e->setFocus(Qt::MouseFocusReason);
    QTest::mouseClick(e, Qt::LeftButton, Qt::NoModifier, QPoint(e->width() - 4, e->height() / 2));
  }
  ASSERT_EQ(focused(), e) << in->objectName().toStdString();
  for (int i = 0; i < text.size(); ++i) {
    QTest::keyClick(focused(), text.at(i).toLatin1());
    ASSERT_EQ(e->text(), text.left(i + 1)) << in->objectName().toStdString() << " after '" << text.left(i + 1).toStdString()
                                           << "'";
  }
  QTest::keyClick(focused(), Qt::Key_Tab);
  QApplication::processEvents();
}

// A reading for a field with this range: the issue's own strings where they
// fit, else a two-decimal value inside the range.
inline QString readingFor(const ui::NumberInput* in) {
  for (const char* c : {"391.7", "0.085", "-1.5", "1025.4", "52.25", "12.5", "7"}) {
    const double v = QString(c).toDouble();
    if (v >= in->minimum() && v <= in->maximum() && v != in->value()) return c;
  }
  const double v = std::round((in->minimum() + 0.37 * (in->maximum() - in->minimum())) * 100.0) / 100.0;
  return QString::number(v, 'f', 2);
}

// Types a reading into every visible, enabled number field of the page and
// checks the value each field holds afterwards. `comma` types the decimal
// separator as ',' (Norwegian keyboards). Returns how many fields it typed in.
inline int typeIntoEveryNumberField(QWizardPage* page, bool comma = false) {
  int n = 0;
  for (ui::NumberInput* in : page->findChildren<ui::NumberInput*>()) {
    if (!in->isVisibleTo(page) || !in->isEnabled()) continue;
    QString typed = readingFor(in);
    const double expected = typed.toDouble();
    if (comma) typed.replace('.', ',');
    typeInto(in, typed);
    EXPECT_DOUBLE_EQ(in->value(), expected) << page->title().toStdString() << ": " << in->objectName().toStdString()
                                            << " typed '" << typed.toStdString() << "'";
    EXPECT_TRUE(in->hasAcceptableInput()) << in->objectName().toStdString();
    ++n;
  }
  return n;
}

// The shortcut letters (after '&') of everything visible on the page and of
// the wizard's buttons; a letter used twice is listed.
inline QStringList duplicateMnemonics(QWizard& wiz) {
  QStringList texts;
  QWizardPage* page = wiz.currentPage();
  for (QLabel* l : page->findChildren<QLabel*>())
    if (l->isVisibleTo(page) && l->buddy()) texts << l->text();
  for (QAbstractButton* b : page->findChildren<QAbstractButton*>())
    if (b->isVisibleTo(page)) texts << b->text();
  for (QGroupBox* g : page->findChildren<QGroupBox*>())
    if (g->isVisibleTo(page)) texts << g->title();
  for (auto w : {QWizard::BackButton, QWizard::NextButton, QWizard::FinishButton, QWizard::CancelButton,
                 QWizard::HelpButton})
    if (wiz.button(w)->isVisible()) texts << wiz.button(w)->text();
  QSet<QChar> seen;
  QStringList dup;
  for (const QString& t : texts) {
    const qsizetype i = t.indexOf(QRegularExpression("&[^&]"));
    if (i < 0) continue;
    const QChar c = t.at(i + 1).toLower();
    if (seen.contains(c)) dup << QString("%1 (%2)").arg(c).arg(QString(t).remove('&'));
    seen.insert(c);
  }
  return dup;
}

// Words on the page a technician cannot act on: CLI flags, code paths, JSON
// files, ids with '_' (channel or point ids). Returns the offending texts.
inline QStringList internalWords(QWizardPage* page) {
  QStringList texts;
  for (QLabel* l : page->findChildren<QLabel*>())
    if (l->isVisibleTo(page)) texts << l->text();
  for (QAbstractButton* b : page->findChildren<QAbstractButton*>())
    if (b->isVisibleTo(page)) texts << b->text();
  for (QGroupBox* g : page->findChildren<QGroupBox*>())
    if (g->isVisibleTo(page)) texts << g->title();
  for (QComboBox* c : page->findChildren<QComboBox*>())
    if (c->isVisibleTo(page))
      for (int i = 0; i < c->count(); ++i) texts << c->itemText(i);
  for (QTableWidget* t : page->findChildren<QTableWidget*>())
    if (t->isVisibleTo(page))
      for (int r = 0; r < t->rowCount(); ++r)
        for (int k = 0; k < t->columnCount(); ++k)
          if (t->item(r, k)) texts << t->item(r, k)->text();
  static const QRegularExpression bad("(^|\\s)--[a-z]|core/|\\.json\\b|\\b[A-Za-z]+_[A-Za-z0-9]+\\b");
  QStringList out;
  for (const QString& t : texts)
    if (bad.match(QString(t).remove(QRegularExpression("<[^>]*>"))).hasMatch()) out << t;
  return out;
}

// Where Tab goes after the page's last field: the first widget after it in
// the window's tab chain (what QWidget::focusNextPrevChild follows) that
// takes Tab focus. It must be Next (or Finish on the last page).
inline QWidget* widgetAfterPageByTab(QWizard& wiz) {
  QWizardPage* page = wiz.currentPage();
  auto tabbable = [](QWidget* w) {
    return w->isVisible() && w->isEnabled() && (w->focusPolicy() & Qt::TabFocus) && !w->focusProxy();
  };
  QWidget* last = nullptr;
  for (QWidget* w = page->nextInFocusChain(); w && w != page; w = w->nextInFocusChain())
    if (page->isAncestorOf(w) && tabbable(w)) last = w;
  if (!last) return nullptr;
  for (QWidget* w = last->nextInFocusChain(); w && w != last; w = w->nextInFocusChain())
    if (tabbable(w)) return page->isAncestorOf(w) ? nullptr : w;
  return nullptr;
}

}  // namespace auv::testing
