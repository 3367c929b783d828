#pragma once
// Slocum glider binary logs as the glider writes them: .dbd/.ebd (flight and
// science computer), .sbd/.tbd (their decimated satellite subsets),
// .mbd/.nbd, and the LZ4-compressed .dcd/.ecd/.scd/.tcd/.mcd/.ncd, recognised
// by content (a `dbd_label: DBD(dinkum_binary_data)file` header, plain or in
// the first LZ4 block). The sensor list is in the file or in a cache named by
// its CRC (see detail/slocum_cache.h for where it is looked up). Every data
// cycle is a row, the first one included (it carries every sensor's value,
// as dbd2asc prints it); only new values (state 10) are samples. Sensors map
// to channels as in the dbd2asc text reader (detail/slocum_channels.h).
#include <filesystem>
#include <string>
#include <string_view>

#include "missionlog/log_reader.h"

namespace auv {

class SlocumBinaryReader final : public LogReader {
 public:
  std::string formatName() const override { return "Slocum binary (.dbd .ebd .sbd .tbd .mbd .nbd, LZ4 .dcd ...)"; }
  // The binary header (plain or compressed); also an empty file with a Slocum
  // extension, so that it is refused with a message that says it is empty.
  bool canRead(const std::filesystem::path& path, std::string_view firstBytes) const override;
  MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                  ReadReport& report) const override;
};

MissionLog readSlocumBinary(const std::filesystem::path& path, const ReadOptions& options, ReadReport& report);
// The same on bytes in memory; `file` names them in messages and places the
// cache search next to it.
MissionLog parseSlocumBinary(std::string_view bytes, const std::filesystem::path& file, const ReadOptions& options,
                             ReadReport& report);

}  // namespace auv
