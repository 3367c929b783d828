#pragma once
// ALSEAMAR SeaExplorer raw files as the glider writes them: navigation
// `<glider>.<mission>.gli.sub.<yo>.gz` (every 10-20 s: Depth, Pitch, Roll,
// Heading, BallastPos, LinPos, AngPos, NavState ...) and payload
// `<glider>.<mission>.pld1.raw.<yo>.gz` (science sensors at their own rates:
// GPCTD/Legato CTD, oxygen, optics), gzip-compressed `;` tables
// (detail/seaexplorer_rows.h, detail/seaexplorer_columns.h). Each file is
// one log on its own time base; a whole mission (the gli and pld1 files of
// every yo) is merged on time by readMission (mission_files.h).
//
// Payload rows arrive in the order the sensors answered, each stamped with
// its own clock, so small steps back in time (< 10 s) are put in order
// instead of being reported as damage (docs/decisions/readers-seaexplorer-raw.md).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "missionlog/log_reader.h"

namespace auv {

// More than any yo file (a 30 MB payload file is a long yo): a gzip file
// that inflates beyond this is damaged or hostile.
inline constexpr std::size_t kSeaExplorerMaxInflatedBytes = std::size_t{1} << 30;

class SeaExplorerRawReader final : public LogReader {
 public:
  std::string formatName() const override { return "SeaExplorer raw (gli.sub / pld1.raw, gzip)"; }
  // gzip (or plain text) whose first line starts with `Timestamp;` or
  // `PLD_REALTIMECLOCK;`.
  bool canRead(const std::filesystem::path& path, std::string_view firstBytes) const override;
  MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                  ReadReport& report) const override;
};

// The same on the file's bytes in memory (gzip or already decompressed);
// `sourceName` names it in messages and its file name gives the yo number.
MissionLog parseSeaExplorerRaw(std::string_view bytes, const std::string& sourceName, const ReadOptions& options,
                               ReadReport& report, std::size_t maxInflatedBytes = kSeaExplorerMaxInflatedBytes);

}  // namespace auv
