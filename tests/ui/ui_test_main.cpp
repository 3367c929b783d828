// GoogleTest main for widget tests: the platform must be chosen before the
// QApplication exists, and gtest_discover_tests runs this binary at build time.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QFont>
#include <cstdlib>

int main(int argc, char** argv) {
  if (!std::getenv("QT_QPA_PLATFORM")) setenv("QT_QPA_PLATFORM", "offscreen", 1);
  if (!std::getenv("XDG_RUNTIME_DIR")) {
    const QString dir = QDir::tempPath() + "/auvballast-xdg";
    QDir().mkpath(dir);
    QFile::setPermissions(dir, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    setenv("XDG_RUNTIME_DIR", dir.toLocal8Bit().constData(), 1);
  }
  QApplication app(argc, argv);
  QApplication::setFont(QFont("DejaVu Sans", 10));
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
