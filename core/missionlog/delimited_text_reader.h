#pragma once
// Vendor text logs: one header line naming the columns (units in brackets,
// parentheses or suffixes), then one row per sample, separated by commas,
// semicolons (with decimal commas), tabs or blanks, with the time as seconds,
// ISO 8601 or `dd.mm.yyyy hh:mm:ss`. The layout is sniffed from the file and
// the columns are matched through channel_aliases.h, unless a ColumnMapping
// says otherwise. HUGIN-style missions written as several files (depth and
// pitch, miscellaneous, navigation, velocity) are merged onto one time base
// by readMerged.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/column_mapping.h"
#include "missionlog/log_reader.h"

namespace auv {

class DelimitedTextReader final : public LogReader {
 public:
  DelimitedTextReader() = default;
  explicit DelimitedTextReader(ColumnMapping mapping) : mapping_(std::move(mapping)) {}

  std::string formatName() const override { return "delimited text (vendor log)"; }
  // Text whose lines split into a header and numeric rows with a time column.
  bool canRead(const std::filesystem::path& path, std::string_view firstBytes) const override;
  MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                  ReadReport& report) const override;
  MissionLog readMerged(const std::vector<std::filesystem::path>& paths, const ReadOptions& options,
                        ReadReport& report) const;
  const ColumnMapping& mapping() const { return mapping_; }

 private:
  ColumnMapping mapping_;
};

MissionLog readDelimitedText(const std::filesystem::path& path, const ColumnMapping& mapping,
                             const ReadOptions& options, ReadReport& report);

// Several files of one mission on the union of their time stamps. Every file
// must have absolute times (date and time, or epoch seconds), or every file
// relative seconds from the same start. A channel found in more than one file
// keeps its name in the first and becomes `<name>_<file stem>` in the others
// (reported). The report adds up all files; its problems name their file.
MissionLog readMerged(const std::vector<std::filesystem::path>& paths, const ColumnMapping& mapping,
                      const ReadOptions& options, ReadReport& report);

// The same reader on text in memory; `sourceName` is used in messages.
MissionLog parseDelimitedText(std::string_view text, const std::string& sourceName,
                              const ColumnMapping& mapping, const ReadOptions& options, ReadReport& report);

// What the reader makes of a file without a mapping, written out as a mapping
// (every column, its channel and unit) for the operator to correct and save.
// Throws InputError when the layout cannot be recognised.
ColumnMapping suggestColumnMapping(const std::filesystem::path& path);
ColumnMapping suggestColumnMapping(std::string_view head, const std::string& sourceName);

}  // namespace auv
