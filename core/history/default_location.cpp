#include "history/default_location.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "common/input_error.h"

namespace fs = std::filesystem;

namespace auv {

std::string userDataFolder() {
  fs::path dir;
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) {
    dir = xdg;
  } else if (const char* home = std::getenv("HOME"); home && *home) {
    dir = fs::path(home) / ".local" / "share";
  } else {
    throw InputError("history", "no location for the history database (HOME and XDG_DATA_HOME are unset)",
                     "set AUVBALLAST_HISTORY to a file");
  }
  return (dir / "auvballast").string();
}

std::string defaultHistoryPath() {
  if (const char* env = std::getenv("AUVBALLAST_HISTORY"); env && *env) return env;
  return (fs::path(userDataFolder()) / "history.sqlite").string();
}

void ensureHistoryFolder(const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) return;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    throw InputError("history", "cannot create the folder '" + dir.string() + "': " + ec.message(),
                     "check its permissions or set AUVBALLAST_HISTORY to a writable file");
  }
}

}  // namespace auv
