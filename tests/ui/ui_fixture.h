#pragma once
// Base fixture for wizard tests: every test gets its own history, autosave
// and settings, so tests run alone, together or in parallel (ctest -j) alike.
#include <gtest/gtest.h>

#include <QSettings>
#include <QDir>
#include <QWidget>

#include "history/timestamp.h"

namespace auv::testing {

class UiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // A fixed folder per test (not a random temporary name): file paths shown
    // on screen must be the same on every machine for the golden images.
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_path_ = QString("/tmp/auvballast-ui-test/%1.%2").arg(info->test_suite_name(), info->name());
    QDir(dir_path_).removeRecursively();
    ASSERT_TRUE(QDir().mkpath(dir_path_));
    qputenv("AUVBALLAST_HISTORY", path("history.sqlite").toLocal8Bit());
    qputenv("AUVBALLAST_AUTOSAVE", path("session.json").toLocal8Bit());
    QSettings().clear();
  }
  void TearDown() override {
    QSettings().clear();
    QDir(dir_path_).removeRecursively();
  }
  QString path(const QString& name) const { return dir_path_ + "/" + name; }
  QString dirPath() const { return dir_path_; }
  // The fixed "now" of all wizard tests (dates and ages on screen are stable).
  static TimePoint fixedNow() { return makeUtc(2026, 5, 20, 12, 0, 0); }

  QString dir_path_;
};

template <class T>
T* find(QWidget& w, const char* name) {
  T* c = w.findChild<T*>(name);
  EXPECT_NE(c, nullptr) << name;
  return c;
}

}  // namespace auv::testing
