#pragma once
// The layout of a vendor text log, decided from the head of the file (up to
// 500 lines): delimiter, decimal mark, header line, an optional units line
// under it, and the comment / `key: value` lines above it.
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/channel_aliases.h"
#include "missionlog/column_mapping.h"
#include "missionlog/detail/line_cells.h"
#include "missionlog/mission_log.h"

namespace auv::detail {

struct Layout {
  Mode mode;
  bool decimalComma = false;
  long long headerLine = 0;
  long long dataFrom = 0;  // first line of the table body
  std::vector<HeaderField> fields;
  std::vector<long> fieldColumn;  // 1-based character column of each header cell
  std::vector<char> textColumn;   // holds only text in the sampled rows
  std::vector<MetadataEntry> preamble;
};

// `head` is the start of the file, `complete` when it is all of it. Every
// delimiter the mapping allows is tried; the one that gives a header line over
// rows of mostly numeric cells wins. Throws InputError (naming `file` and the
// line) for UTF-16 or binary data, bare carriage returns, no data lines, no
// usable delimiter, no header line, or too many columns.
Layout sniffLayout(std::string_view head, bool complete, const ColumnMapping& mapping, const std::string& file);

// True for a cell that is a time stamp: ISO 8601, dd.mm.yyyy [hh:mm:ss], a
// bare time of day or a bare date.
bool isAbsoluteTimeText(std::string_view cell);

}  // namespace auv::detail
