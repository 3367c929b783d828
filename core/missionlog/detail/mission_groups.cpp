#include "missionlog/detail/mission_groups.h"

#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/seaexplorer_rows.h"

namespace auv::detail {
namespace {

// Slocum binary kinds and their LZ4-compressed forms (the other helper's
// reader reads them; here they only need to pair up by name).
constexpr std::string_view kSlocumExtensions[] = {".dbd", ".ebd", ".sbd", ".tbd", ".mbd", ".nbd",
                                                  ".dcd", ".ecd", ".scd", ".tcd", ".mcd", ".ncd",
                                                  ".dba", ".eba", ".sba", ".tba", ".mba", ".nba"};

constexpr std::string_view kNonLogExtensions[] = {".m",   ".yml", ".yaml", ".md",  ".json", ".cac", ".ccc",
                                                  ".pdf", ".png", ".jpg",  ".jpeg", ".html", ".xml", ".py",
                                                  ".sh",  ".zip", ".mi",   ".ma",   ".cfg",  ".ini", ".kml"};

}  // namespace

std::string missionGroupKey(std::string_view fileName) {
  const SeaExplorerName sx = parseSeaExplorerName(fileName);
  if (sx.yo >= 0) return lower(sx.glider) + "." + lower(sx.mission) + "#" + std::to_string(sx.yo);
  const std::size_t dot = fileName.rfind('.');
  if (dot != std::string_view::npos) {
    const std::string ext = lower(fileName.substr(dot));
    for (std::string_view e : kSlocumExtensions)
      if (ext == e) return lower(fileName.substr(0, dot));
  }
  return std::string(fileName);
}

std::string missionStreamKey(std::string_view fileName) {
  const SeaExplorerName sx = parseSeaExplorerName(fileName);
  if (sx.yo >= 0) return lower(sx.glider) + "." + lower(sx.mission) + "." + sx.stream;
  const std::size_t dot = fileName.rfind('.');
  if (dot != std::string_view::npos) {
    const std::string ext = lower(fileName.substr(dot));
    for (std::string_view e : kSlocumExtensions)
      if (ext == e) return ext;
  }
  return {};
}

bool isKnownNonLogFile(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  if (name.empty() || name.front() == '.' || name.back() == '~') return true;
  const std::string ext = lower(path.extension().string());
  for (std::string_view e : kNonLogExtensions)
    if (ext == e) return true;
  const std::string stem = lower(path.stem().string());
  return stem == "readme" || stem == "license" || stem == "licence";
}

}  // namespace auv::detail
