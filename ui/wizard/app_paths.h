#pragma once
// Where the GUI keeps its files. Each can be overridden by an environment
// variable, which the tests use to work in a temporary directory:
//   AUVBALLAST_HISTORY   the SQLite history (default $XDG_DATA_HOME/auvballast/history.sqlite,
//                        the same file as the CLI's: history/default_location.h)
//   AUVBALLAST_AUTOSAVE  the unfinished session (default $XDG_DATA_HOME/auvballast/session.json)
//   AUVBALLAST_DOCS      the folder holding user-guide.md
#include <QString>

namespace auv::ui {

QString historyFilePath();
QString autosaveFilePath();
// docs/user-guide.md: $AUVBALLAST_DOCS, the installed share/doc/auvballast,
// else the source tree's docs/.
QString userGuidePath();

}  // namespace auv::ui
