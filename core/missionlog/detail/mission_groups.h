#pragma once
// Which files of a mission belong together: the files one vehicle wrote for
// the same stretch of time from different computers or sensor streams (a
// Slocum segment's .dbd and .ebd, a SeaExplorer yo's gli.sub and pld1.raw)
// form one group; a Seaglider dive file is a group of its own. Groups follow
// each other in time; files within a group overlap by design.
#include <filesystem>
#include <string>
#include <string_view>

namespace auv::detail {

// The group a file belongs to, from its name: `sea046.45.gli.sub.10.gz` ->
// "sea046.45#10", `01600001.dbd` / `01600001.ebd` -> "01600001", any other
// file -> its own name.
std::string missionGroupKey(std::string_view fileName);

// The stream a file belongs to: files of one stream follow each other in
// time and must not overlap (`gli` and `pld1` for SeaExplorer, the extension
// for Slocum: dbd, ebd ...); "" for any other file (all one stream).
std::string missionStreamKey(std::string_view fileName);

// True for files that are certainly not logs and are met in mission folders
// (calibration scripts, deployment YAML, READMEs, Slocum sensor-list caches,
// pictures): skipped without opening them.
bool isKnownNonLogFile(const std::filesystem::path& path);

}  // namespace auv::detail
