#pragma once
// The mission-log interchange CSV (shared/formats/mission-log-csv.md, v1):
// `# key: value` metadata, a `name [unit]` header, one row per sample, empty
// or NaN cells = not sampled. Reading converts table columns to canonical
// units and survives damaged files (see ReadReport); writing produces exactly
// what the reader reads back, bit for bit (shortest round-trip numbers).
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "missionlog/log_reader.h"

namespace auv {

class InterchangeCsvReader final : public LogReader {
 public:
  std::string formatName() const override { return "mission-log CSV v1"; }
  // Metadata lines, then a comma-separated header with a `time` column.
  bool canRead(const std::filesystem::path& path, std::string_view firstBytes) const override;
  MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                  ReadReport& report) const override;
};

// Reads a file in large blocks (no mapping, bounded memory besides the
// columns). Throws InputError (file:line:column) when nothing usable is left,
// ReadCancelled when options.progress returns false.
MissionLog readInterchangeCsv(const std::filesystem::path& path, const ReadOptions& options,
                              ReadReport& report);
MissionLog readInterchangeCsv(const std::filesystem::path& path);

// The same parser on text already in memory; `sourceName` is used in messages.
MissionLog parseInterchangeCsv(std::string_view text, const std::string& sourceName,
                               const ReadOptions& options, ReadReport& report);

// Writes metadata, `time [s]` and every channel in its current unit. Throws
// InputError for a log that would not read back as written (a channel name
// with a comma or bracket, a metadata key with a colon, non-increasing time,
// infinite values, channel length != row count), or when the file cannot be
// written.
void writeInterchangeCsv(const MissionLog& log, const std::filesystem::path& path);
void writeInterchangeCsv(const MissionLog& log, std::ostream& out);

}  // namespace auv
