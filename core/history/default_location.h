#pragma once
// The one place the history lives for every front end (CLI and wizard), so
// that `auvballast history --config ID` sees what the wizard saved:
//   $AUVBALLAST_HISTORY, else $XDG_DATA_HOME/auvballast/history.sqlite,
//   else $HOME/.local/share/auvballast/history.sqlite.
#include <string>

namespace auv {

// $XDG_DATA_HOME/auvballast (else $HOME/.local/share/auvballast): the
// user's data folder (history, the wizard's unfinished session). Does not
// touch the disk. Throws InputError when neither variable is set.
std::string userDataFolder();

// The history's path by the rule above; does not touch the disk.
std::string defaultHistoryPath();

// Creates the folder holding `path` if it is missing (first launch for a
// user). Throws InputError naming the folder when it cannot be created.
void ensureHistoryFolder(const std::string& path);

}  // namespace auv
