// GoogleTest main for widget tests: the platform must be chosen before the
// QApplication exists, and gtest_discover_tests runs this binary at build time.
// Everything that could differ between machines or runs is pinned here so
// that screenshots can be compared with committed goldens: the fonts
// fontconfig may use (only Debian's DejaVu folder, whatever else is
// installed), the style, the font (DejaVu Sans), no cursor blinking, and
// private settings/data folders.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QFont>
#include <QSettings>
#include <QStandardPaths>
#include <QStyleFactory>
#include <QTemporaryDir>
#include <cstdlib>
#include <iostream>

#include "wizard/pinned_fonts.h"

#include "wizard/background_task.h"
#include "wizard/operator_wizard.h"

int main(int argc, char** argv) {
  if (!std::getenv("QT_QPA_PLATFORM")) setenv("QT_QPA_PLATFORM", "offscreen", 1);
  if (!std::getenv("XDG_RUNTIME_DIR")) {
    const QString dir = QDir::tempPath() + "/auvballast-xdg";
    QDir().mkpath(dir);
    QFile::setPermissions(dir, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    setenv("XDG_RUNTIME_DIR", dir.toLocal8Bit().constData(), 1);
  }
  const QString fonts = auv::ui::pinFontsToDejaVu(QDir::tempPath() + "/auvballast-ui-test-fonts");
  if (!fonts.isEmpty()) {
    std::cerr << "ui_test: " << fonts.toStdString() << "\n";
    return 1;
  }
  QApplication app(argc, argv);
  QApplication::setOrganizationName("auvballast-test");
  QApplication::setApplicationName("auvballast-test");
  QStandardPaths::setTestModeEnabled(true);
  // Settings of this process only (geometry, last folder): never the user's.
  QTemporaryDir settings_dir(QDir::tempPath() + "/auvballast-ui-test-XXXXXX");
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings_dir.path());
  auv::ui::pinRenderingLook();
  QApplication::setCursorFlashTime(0);  // a blinking cursor would make screenshots random
  // No modal box may wait for a person: questions get the affirmative answer
  // (what the tests before these questions did), and tests that check a
  // question set their own asker.
  auv::ui::OperatorWizard::setDefaultAsker([](const QString&, const QString&, bool) { return true; });
  // A page's background work (analysis, plots) on the small test logs lands
  // before the page shows, whatever the machine's load, so tests and goldens
  // see whole pages; tests of the busy state (big_log_test) use the
  // product's grace.
  auv::ui::BackgroundTask::setGraceMs(60000);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
