#pragma once
// Slocum glider ASCII logs as written by dbd2asc / dba_merge (.dba, .asc):
// `key: value` header tags (dbd_label:, num_ascii_tags:, sensors_per_cycle:,
// num_label_lines:, segment_filename_0: ...), three label lines (sensor
// names, units, bytes), then one whitespace-separated row per cycle with NaN
// where a sensor was not updated. Engineering rows are timed by
// m_present_time, science rows by sci_m_present_time; the two streams are
// repaired separately and merged onto one time base. Table sensors become the
// format's channels in its units (m_pitch rad -> pitch deg, m_battpos in ->
// battery_position mm, sci_water_pressure bar -> pressure dbar, ...); every
// other sensor that was ever sampled is kept under its own name and unit.
#include <filesystem>
#include <string>
#include <string_view>

#include "missionlog/log_reader.h"

namespace auv {

class SlocumAsciiReader final : public LogReader {
 public:
  std::string formatName() const override { return "Slocum ASCII (dbd2asc .dba/.asc)"; }
  // The file starts with `dbd_label:`.
  bool canRead(const std::filesystem::path& path, std::string_view firstBytes) const override;
  MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                  ReadReport& report) const override;
};

MissionLog readSlocumAscii(const std::filesystem::path& path, const ReadOptions& options, ReadReport& report);
MissionLog parseSlocumAscii(std::string_view text, const std::string& sourceName, const ReadOptions& options,
                            ReadReport& report);

}  // namespace auv
