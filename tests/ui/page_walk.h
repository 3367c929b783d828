#pragma once
// Every wizard sequence on the bundled demo data, walked page by page as a
// technician does (Enter from the page's last field), with what a person
// reads on each page collected as plain text. Used by every_page_test.cpp
// for the words, keyboard and screen-size checks of issue 14 (items 7, 8).
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextDocument>
#include <QtCharts/QAbstractAxis>
#include <QtCharts/QAbstractSeries>
#include <QtCharts/QChartView>
#include <functional>
#include <string>
#include <vector>

#include "pages/log_import_page.h"
#include "pages/model_check_page.h"
#include "wizard/operator_wizard.h"

namespace auv::testing {

// One sequence: its name, the session it starts from and, when it needs a
// past, a history to seed (post mission).
struct WizardSequence {
  std::string name;
  std::function<ui::WizardState(const QString& scratch_dir)> session;
  std::function<void(const QString& history_file)> seed_history;
  // The page the walk ends on (checked, not left), -1: through Finish.
  int last_page = -1;
};

// HUGIN, Delphin2, Slocum and Seaglider first missions; HUGIN, Slocum and
// Delphin2 post missions through to the plan (as far as each kind goes).
std::vector<WizardSequence> everyWizardSequence();

// Lets queued work (imports, model checks) finish and the page become
// complete, at most `timeout_ms`. The HUGIN post-mission model check takes
// about 10 s alone; on a loaded two-core machine (two test runs at once) it
// took over 60 s, so the bound is 180 s: a hang still fails.
inline void settlePage(ui::OperatorWizard& wiz, int timeout_ms = 180000) {
  QElapsedTimer t;
  t.start();
  auto busy = [&wiz] {
    QWizardPage* p = wiz.currentPage();
    if (auto* import = qobject_cast<ui::LogImportPage*>(p); import && import->job().running()) return true;
    if (auto* check = qobject_cast<ui::ModelCheckPage*>(p); check && check->job().running()) return true;
    return p && !p->isComplete();
  };
  while (busy() && t.elapsed() < timeout_ms) QApplication::processEvents(QEventLoop::AllEvents, 20);
  QApplication::processEvents();
}

// One text a person reads on the page and where it is (for the message).
struct VisibleText {
  QString where;  // "label 'analysis_notes'", "table 'segments' header", ...
  QString text;   // as read: HTML tags removed, entities decoded
};

inline QString plain(const QString& t) {
  if (!Qt::mightBeRichText(t)) return t;
  QTextDocument d;
  d.setHtml(t);
  return d.toPlainText();
}

inline QString nameOf(const QObject* o) {
  return o->objectName().isEmpty() ? QString(o->metaObject()->className()) : "'" + o->objectName() + "'";
}

// Everything the current page shows in words: title, labels, buttons, group
// titles, list items, table cells and headers, tab names, placeholders,
// chart titles, axis titles and legend entries, and the wizard's buttons.
inline std::vector<VisibleText> visibleTexts(ui::OperatorWizard& wiz) {
  std::vector<VisibleText> out;
  QWizardPage* page = wiz.currentPage();
  auto add = [&out](const QString& where, const QString& text) {
    if (!text.trimmed().isEmpty()) out.push_back({where, plain(text)});
  };
  auto shown = [page](const QWidget* w) { return w->isVisibleTo(page); };
  add("page title", page->title());
  add("page subtitle", page->subTitle());
  for (QLabel* l : page->findChildren<QLabel*>())
    if (shown(l)) add("label " + nameOf(l), l->text());
  for (QAbstractButton* b : page->findChildren<QAbstractButton*>())
    if (shown(b)) add("button " + nameOf(b), b->text());
  for (QGroupBox* g : page->findChildren<QGroupBox*>())
    if (shown(g)) add("group " + nameOf(g), g->title());
  for (QComboBox* c : page->findChildren<QComboBox*>())
    if (shown(c))
      for (int i = 0; i < c->count(); ++i) add("list " + nameOf(c), c->itemText(i));
  for (QLineEdit* e : page->findChildren<QLineEdit*>())
    if (shown(e)) add("field " + nameOf(e) + " placeholder", e->placeholderText());
  for (QTabWidget* t : page->findChildren<QTabWidget*>())
    if (shown(t))
      for (int i = 0; i < t->count(); ++i) add("tab " + nameOf(t), t->tabText(i));
  for (QTableWidget* t : page->findChildren<QTableWidget*>()) {
    if (!shown(t)) continue;
    for (int k = 0; k < t->columnCount(); ++k)
      if (auto* h = t->horizontalHeaderItem(k); h && !t->isColumnHidden(k)) add("table " + nameOf(t) + " header", h->text());
    for (int r = 0; r < t->rowCount(); ++r)
      for (int k = 0; k < t->columnCount(); ++k)
        if (t->item(r, k) && !t->isColumnHidden(k) && !t->isRowHidden(r))
          add(QString("table %1 row %2").arg(nameOf(t)).arg(r + 1), t->item(r, k)->text());
  }
  for (QChartView* v : page->findChildren<QChartView*>()) {
    if (!shown(v) || !v->chart()) continue;
    add("chart " + nameOf(v) + " title", v->chart()->title());
    for (QAbstractAxis* a : v->chart()->axes())
      if (a->isVisible()) add("chart " + nameOf(v) + " axis", a->titleText());
    for (QAbstractSeries* s : v->chart()->series())
      if (s->isVisible()) add("chart " + nameOf(v) + " legend", s->name());
  }
  for (auto b : {QWizard::BackButton, QWizard::NextButton, QWizard::FinishButton, QWizard::CancelButton,
                 QWizard::HelpButton})
    if (wiz.button(b)->isVisible()) add("wizard button", wiz.button(b)->text());
  return out;
}

// Words a technician cannot act on, in `text`: a CLI flag ("--bg-mm"), a
// code path ("core/sim"), a JSON file or path (".json"), an id with '_'
// ("fore_port", "vertical_velocity"). File paths the technician chose or
// was shown as paths (absolute, or a log file name) are not words: skipped.
inline QStringList internalWordsIn(QString text) {
  static const QRegularExpression path(R"((^|\s|\()(/[^\s)]+|[\w.-]+\.(csv|dba|asc|nc|txt|sqlite|pdf|png|log))\b)");
  text.replace(path, " ");
  static const QRegularExpression bad(R"(--|core/|\.json\b|\w*_\w*)");
  QStringList hits;
  for (auto it = bad.globalMatch(text); it.hasNext();) hits << it.next().captured(0);
  return hits;
}

// The page widget Tab leaves last before the wizard's buttons (nullptr if
// none takes Tab focus), following the window's tab chain from the page.
inline QWidget* lastPageWidgetByTab(ui::OperatorWizard& wiz) {
  QWizardPage* page = wiz.currentPage();
  auto tabbable = [](QWidget* w) {
    return w->isVisible() && w->isEnabled() && (w->focusPolicy() & Qt::TabFocus) && !w->focusProxy();
  };
  QWidget* last = nullptr;
  for (QWidget* w = page->nextInFocusChain(); w && w != page; w = w->nextInFocusChain())
    if (page->isAncestorOf(w) && tabbable(w)) last = w;
  return last;
}

}  // namespace auv::testing
