#pragma once
// The part of an interchange CSV before the rows (shared/formats/
// mission-log-csv.md): `# key: value` metadata lines, then one header line of
// comma-separated `name [unit]` cells naming a `time` column.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/mission_log.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"
#include "missionlog/unit_conversion.h"

namespace auv::detail {

// One header cell, `name [unit]`; anything else is not well formed.
struct HeaderCell {
  std::string text;  // unquoted
  std::string name, unit;
  bool bracket = false;
  bool well_formed = true;
};

HeaderCell parseHeaderCell(std::string_view raw);

// The body of a `# key: value` line (after the '#'); without a colon the key
// is empty and the whole text is the value.
MetadataEntry parseMetadataLine(std::string_view body);

struct InterchangeColumn {
  std::string name, unit, source_unit;
  UnitConversion conv;  // to `unit` (the format's unit of a table channel)
  bool ignored = false;
};

struct InterchangeHeader {
  std::vector<InterchangeColumn> columns;  // one per header cell
  std::size_t time_column = 0;
  bool iso_time = false;  // `time [iso8601]`: times are read as epoch seconds
};

// The header line, line `lineNo` of `file`. Columns without a name or not
// written `name [unit]` are ignored and repeated names renamed (noted in
// `report`); throws InputError when there is no `time` column, a table
// channel's unit cannot be converted to the format's, or the line is not a
// comma-separated header.
InterchangeHeader parseInterchangeHeader(std::string_view line, const std::string& file, long long lineNo,
                                         const ReadOptions& options, ReadReport& report);

}  // namespace auv::detail
