#pragma once
#include <QLocale>

namespace auv::ui {

// Installs the application's translation for `locale` (English needs none;
// Norwegian bokmål ships as :/i18n/auvballast_nb.qm, compiled from
// resources/translations/auvballast_nb.ts by lrelease at build time).
// Returns true if a translation was installed. A second call replaces the first.
bool installTranslation(const QLocale& locale);
void removeTranslation();

}  // namespace auv::ui
