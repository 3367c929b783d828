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
}  // namespace

void removeTranslation() {
  if (current()) {
    QCoreApplication::removeTranslator(current().get());
    current().reset();
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
  return true;
}

}  // namespace auv::ui
