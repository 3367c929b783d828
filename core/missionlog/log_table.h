#pragma once
// The common tail of the vendor-format readers (delimited text, Slocum ASCII,
// glider NetCDF): a reader fills a LogTable with what the file says, and the
// functions here apply the same rules as the interchange CSV reader (see
// docs/decisions/missionlog-damaged-rows.md and missionlog-units.md): units
// converted to the format table's, fill values blanked, rows without a time
// skipped, time order repaired by dropping the fewest rows, duplicate times
// merged, long gaps noted. Several tables (files, Slocum science/engineering
// streams, NetCDF dimensions) can then be merged onto one time base.
#include <string>
#include <vector>

#include "common/input_error.h"
#include "missionlog/mission_log.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv {

struct TableColumn {
  std::string name;         // channel name in the log
  std::string source_name;  // column / sensor / variable name in the file
  std::string unit;         // unit of `values` (normalised spelling), "" = not stated
  std::string source_unit;  // as written in the file ("" = none)
  // Extra channels keep their unit unless this names one to convert to;
  // channels of the format table always go to the table's unit.
  std::string to_unit;
  double scale = 1.0;   // applied to each value first (mapping rules, sign flips)
  double offset = 0.0;
  InputLocation where;  // header cell / variable, for messages
  std::vector<double> values;  // one per row, or empty = never sampled
};

struct LogTable {
  std::string file;
  std::vector<double> time;  // s; seconds since 1970 UTC when `epoch`
  bool epoch = false;
  // Where each row came from: a 1-based line (text files) or, when
  // `record_dimension` is set, a 0-based index along that NetCDF dimension.
  std::vector<long long> row_where;
  std::string record_dimension;
  std::vector<TableColumn> columns;
  std::vector<MetadataEntry> metadata;
  std::string tag;  // short name used when merged channels collide (file stem, dimension)
};

// Converts units (throws InputError naming the column for a table channel in
// a unit of another quantity), blanks out-of-range and physically impossible
// values, drops rows without a usable time and repairs the time order. Adds to
// rows_skipped, rows_merged, cells_blanked and the problem list; the reader
// counts data_lines (and its own skips) itself. Afterwards time is finite and
// strictly increasing and every column has one value per row.
void tidyTable(LogTable& table, const ReadOptions& options, ReadReport& report);

enum class MergeNames {
  kCombine,  // same name = same channel (Slocum streams): values are combined
  kRename,   // same name = another sensor (separate files): later ones get `_<tag>`
};

// Tidied tables -> one table on the union of their time stamps (exactly equal
// times share a row; rows_merged counts the rows saved that way). Throws
// InputError when some tables have absolute and others relative time.
LogTable mergeTables(std::vector<LogTable> tables, MergeNames names, const ReadOptions& options,
                     ReadReport& report);

// A tidied table -> MissionLog. Absolute times become seconds since `# start:`
// (the first time, rounded down to the millisecond, written as ISO 8601).
// Columns that were never sampled are left out when `dropEmpty`.
MissionLog finishTable(LogTable table, ReadReport& report, bool dropEmpty);

// `name` made safe for the interchange CSV header (no ',', '[', ']', '"',
// control bytes or blanks at the ends), for channels named after file content.
std::string safeChannelName(std::string_view name);

// A cell or name for a message: control bytes (and non-ASCII bytes unless
// `keepUtf8`, for header texts such as "Ønsket dybde") escaped, capped.
std::string printableText(std::string_view s, std::size_t max = 24, bool keepUtf8 = false);

// `s` if it is valid UTF-8, else read as Latin-1 / Windows-1252 (the other
// encoding European loggers write) and converted, so that "Temp (\xB0C)"
// becomes "Temp (°C)" and every name can go into JSON.
std::string toValidUtf8(std::string_view s);

// Shortest round-trip text of a number, for messages.
std::string numberText(double v);
// Three significant digits, for a figure the reader computed (a span, an
// extreme) rather than a value as the file wrote it.
std::string roundedText(double v);

}  // namespace auv
