#pragma once
// A saved description of one vehicle's vendor text logs: delimiter, decimal
// mark, which column is the time and how it is written, and which column is
// which channel in which unit. Stored as JSON (docs/formats/column-mapping.md)
// so that a technician maps a new logger once and every later import of that
// vehicle's logs reads the same way. Without a mapping the delimited-text
// reader guesses all of this from the file (channel_aliases.h).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "missionlog/channel_aliases.h"
#include "missionlog/mission_log.h"

namespace auv {

enum class Delimiter { kAuto, kComma, kSemicolon, kTab, kWhitespace };
enum class DecimalMark { kAuto, kPoint, kComma };
enum class TimeFormat {
  kAuto,
  kSeconds,       // a number in the time unit (s unless stated), relative to an unknown start
  kEpochSeconds,  // a number of seconds since 1970-01-01T00:00:00Z
  kIso8601,       // 2026-05-14T08:12:00.5Z
  kDayMonthYear,  // 14.05.2026 08:12:00.5
  kTimeOfDay,     // 08:12:00.5, with the date from `date_column` or counted from midnight
};

struct ColumnRule {
  std::string header;   // header text, or its name without the unit; case, blanks and punctuation ignored
  std::string channel;  // channel in the log (a format name such as "depth_cmd", or any other name)
  std::string unit;     // unit of the values in the file; "" = from the header, the alias or the format
  double scale = 1.0;   // value = file value * scale + offset, before the unit conversion
  double offset = 0.0;  //   (e.g. scale -1 for a logger that counts roll port-down positive)
  bool ignore = false;  // leave this column out
};

struct TimeRule {
  std::string column;  // "" = the column the aliases call time
  TimeFormat format = TimeFormat::kAuto;
  std::string unit;         // of numeric times ("" = from the header, else s)
  std::string date_column;  // a separate date column for kTimeOfDay
  // The logger clock runs at UTC + this; unset = UTC assumed (and noted in
  // the report) for times written without a zone.
  std::optional<double> utc_offset_hours;
};

struct ColumnMapping {
  std::string vehicle;
  std::string description;
  Delimiter delimiter = Delimiter::kAuto;
  DecimalMark decimal = DecimalMark::kAuto;
  TimeRule time;
  std::vector<ColumnRule> columns;
  std::vector<MetadataEntry> metadata;  // added to every log read with this mapping

  // Throws InputError naming the file and the JSON path of a bad field
  // (unknown keys are refused, so a typo cannot silently do nothing).
  static ColumnMapping load(const std::filesystem::path& path);
  static ColumnMapping fromJson(const std::string& text, const std::string& sourceName);
  std::string toJson() const;
  void save(const std::filesystem::path& path) const;  // InputError if it cannot be written

  // The rule for a header cell, or nullptr.
  const ColumnRule* ruleFor(const HeaderField& field) const;
  // True if `field` is the column `name` refers to (same matching as ruleFor).
  static bool matches(const std::string& name, const HeaderField& field);
};

const char* toString(Delimiter d);
const char* toString(DecimalMark d);
const char* toString(TimeFormat f);

}  // namespace auv
