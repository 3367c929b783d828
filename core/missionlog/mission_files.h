#pragma once
// A whole mission as the vehicle wrote it: many files, often in one folder
// (ten Seaglider dive files, a Slocum flight's .dbd/.ebd segments, the
// gli.sub/pld1.raw pair of every SeaExplorer yo). This is the one entry point
// every front end uses for `--log` (CLI) and the wizard's import page:
//
//   1. folders are expanded to their files (not recursively, in name order);
//      files no reader recognises and known non-log files (calibration .m,
//      deployment .yml, READMEs, caches) are skipped and listed in the
//      metadata, not reported as problems;
//   2. each file is read through the reader registry (by content);
//   3. the files are grouped (detail/mission_groups.h: a Slocum segment's
//      .dbd+.ebd, a SeaExplorer yo's gli+pld1, one Seaglider dive) and
//      merged on time: channels of the same name and unit are one channel,
//      equal time stamps share a row;
//   4. overlaps between groups (a file given twice, clocks that disagree) and
//      gaps between groups (a missing dive or yo) are reported once for the
//      mission, not once per file. Same-time values that agree (a GPS fix at
//      the end of one dive file and the start of the next) merge silently.
//
// One file given alone is read exactly as LogReaderRegistry::read reads it.
#include <filesystem>
#include <string>
#include <vector>

#include "missionlog/log_reader.h"
#include "missionlog/mission_log.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv {

struct MissionFiles {
  std::vector<std::filesystem::path> logs;     // to read, in the order given / name order within a folder
  std::vector<std::filesystem::path> skipped;  // found in folders, not logs
};

// Throws InputError for a path that does not exist, and for a folder with no
// file that any reader recognises (naming what it skipped).
MissionFiles expandMissionPaths(const std::vector<std::filesystem::path>& inputs, const LogReaderRegistry& registry);

// One log read from one file, as mergeMission takes it.
struct MissionPart {
  std::string file;
  MissionLog log;
  ReadReport report;
};

// Merges logs of one mission (steps 3 and 4 above). The report adds up the
// parts' reports (their problems keep naming their files), plus the mission's
// own overlap / gap / conflict notes. Throws InputError when some parts have
// absolute time (`# start:`) and others only relative seconds.
MissionLog mergeMission(std::vector<MissionPart> parts, const ReadOptions& options, ReadReport& report);

// Steps 1-4. `inputs` are files and folders. Progress runs over all files.
MissionLog readMission(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options,
                       ReadReport& report, const LogReaderRegistry& registry);
MissionLog readMission(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options,
                       ReadReport& report);

// A short name for the inputs in messages and reports: the file name, the
// folder name, or "<first> and N more".
std::string missionLabel(const std::vector<std::filesystem::path>& inputs);

}  // namespace auv
