#include "wizard/translations.h"

#include <QCoreApplication>
#include <QTranslator>
#include <memory>

namespace auv::ui {
namespace {
std::unique_ptr<QTranslator>& current() {
  static std::unique_ptr<QTranslator> t;
  return t;
}
// The default locale before any translation: numbers go back to it.
const QLocale& startLocale() {
  static const QLocale l;
  return l;
}
}  // namespace

void removeTranslation() {
  if (current()) {
    QCoreApplication::removeTranslator(current().get());
    current().reset();
    QLocale::setDefault(startLocale());
  }
}

bool installTranslation(const QLocale& locale) {
  removeTranslation();
  auto t = std::make_unique<QTranslator>();
  // Norwegian "no"/"nn" users read bokmål better than English.
  QLocale l = locale;
  if (l.language() == QLocale::NorwegianNynorsk) l = QLocale(QLocale::NorwegianBokmal);
  if (!t->load(l, "auvballast", "_", ":/i18n")) return false;
  QCoreApplication::installTranslator(t.get());
  current() = std::move(t);
  // Numbers in the same language as the words ("1025,4" under nb), typed and shown.
  (void)startLocale();
  QLocale::setDefault(l);
  return true;
}

}  // namespace auv::ui
