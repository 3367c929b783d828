#include "missionlog/detail/slocum_cache.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>
#include <unistd.h>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/slocum_lz4.h"

namespace auv::detail {
namespace fs = std::filesystem;

namespace {

bool validCrc(std::string_view crc) {
  if (crc.empty() || crc.size() > 16) return false;
  for (char c : crc)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'))) return false;
  return true;
}

}  // namespace

fs::path slocumUserCacheDir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg == '/') return fs::path(xdg) / "auvballast" / "slocum-cache";
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".cache" / "auvballast" / "slocum-cache";
  return {};
}

std::vector<fs::path> slocumCacheSearchPath(const fs::path& optionDir, const fs::path& dataFile, bool userCache) {
  std::vector<fs::path> dirs;
  auto add = [&](fs::path d) {
    if (d.empty()) return;
    for (const auto& e : dirs)
      if (e == d) return;
    dirs.push_back(std::move(d));
  };
  add(optionDir);
  if (!dataFile.empty()) add(dataFile.has_parent_path() ? dataFile.parent_path() : fs::path("."));
  if (userCache) add(slocumUserCacheDir());
  return dirs;
}

std::optional<fs::path> findSlocumCache(const std::vector<fs::path>& dirs, std::string_view crc) {
  if (!validCrc(crc)) return std::nullopt;
  const std::string want = lower(crc);
  for (const auto& d : dirs) {
    std::error_code ec;
    std::optional<fs::path> ccc;
    for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec)) {
      const fs::path& p = it->path();
      if (lower(p.stem().string()) != want) continue;
      const std::string ext = lower(p.extension().string());
      if (ext == ".cac") return p;
      if (ext == ".ccc") ccc = p;
    }
    if (ccc) return ccc;
  }
  return std::nullopt;
}

std::string loadSlocumCache(const fs::path& cacheFile) {
  std::ifstream in(cacheFile, std::ios::binary);
  std::ostringstream s;
  if (in) s << in.rdbuf();
  if (!in)
    throw InputError("sensor_list_crc", "cannot read the sensor-list cache", "check the file's permissions",
                     {cacheFile.string(), 0, 0});
  if (lower(cacheFile.extension().string()) == ".ccc") return slocumLz4Decompress(s.str(), cacheFile.string());
  return s.str();
}

bool storeSlocumCache(const fs::path& dir, std::string_view crc, std::string_view sensorLines) {
  if (dir.empty() || !validCrc(crc)) return false;
  if (findSlocumCache({dir}, crc)) return true;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return false;
  const fs::path target = dir / (lower(crc) + ".cac");
  // Written under a private name and renamed, so that a reader in another
  // process never sees half a cache.
  const fs::path tmp = dir / (lower(crc) + ".cac.tmp" + std::to_string(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(sensorLines.data(), static_cast<std::streamsize>(sensorLines.size()));
    if (!out) {
      fs::remove(tmp, ec);
      return false;
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) fs::remove(tmp, ec);
  return !ec;
}

}  // namespace auv::detail
