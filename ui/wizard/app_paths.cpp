#include "wizard/app_paths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include "common/input_error.h"
#include "history/default_location.h"

namespace auv::ui {

QString historyFilePath() {
  try {
    return QString::fromStdString(defaultHistoryPath());
  } catch (const InputError&) {
    return QString();  // no HOME: the wizard's history() says why
  }
}

QString autosaveFilePath() {
  const QString env = qEnvironmentVariable("AUVBALLAST_AUTOSAVE");
  if (!env.isEmpty()) return env;
  try {
    return QString::fromStdString(userDataFolder()) + "/session.json";
  } catch (const InputError&) {
    return QDir::tempPath() + "/auvballast-session.json";
  }
}

QString userGuidePath() {
  const QString env = qEnvironmentVariable("AUVBALLAST_DOCS");
  if (!env.isEmpty()) return env + "/user-guide.md";
  const QString installed =
      QCoreApplication::applicationDirPath() + "/../share/doc/auvballast/user-guide.md";
  if (QFileInfo::exists(installed)) return QDir::cleanPath(installed);
  return QStringLiteral(AUV_SOURCE_DOCS_DIR "/user-guide.md");
}

}  // namespace auv::ui
