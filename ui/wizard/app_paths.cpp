#include "wizard/app_paths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace auv::ui {
namespace {

QString fromEnvOr(const char* name, const QString& fallback) {
  const QString v = qEnvironmentVariable(name);
  return v.isEmpty() ? fallback : v;
}

QString appData(const QString& file) {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/" + file;
}

}  // namespace

QString historyFilePath() { return fromEnvOr("AUVBALLAST_HISTORY", appData("history.sqlite")); }

QString autosaveFilePath() { return fromEnvOr("AUVBALLAST_AUTOSAVE", appData("session.json")); }

QString userGuidePath() {
  const QString env = qEnvironmentVariable("AUVBALLAST_DOCS");
  if (!env.isEmpty()) return env + "/user-guide.md";
  const QString installed =
      QCoreApplication::applicationDirPath() + "/../share/doc/auvballast/user-guide.md";
  if (QFileInfo::exists(installed)) return QDir::cleanPath(installed);
  return QStringLiteral(AUV_SOURCE_DOCS_DIR "/user-guide.md");
}

}  // namespace auv::ui
