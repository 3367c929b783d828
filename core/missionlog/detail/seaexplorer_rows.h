#pragma once
// The text of one SeaExplorer raw file (already decompressed) as a LogTable:
// a `;`-separated header (every line ends with `;`), then one row per record
// with the time in the first column as `dd/mm/yyyy HH:MM:SS[.fff]` (ISO 8601
// and `dd.mm.yyyy` are accepted too). Columns differ between files and
// firmware versions, so each file's own header decides.
#include <string>
#include <string_view>

#include "missionlog/log_table.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv::detail {

// What a SeaExplorer file name says: `sea046.45.gli.sub.10.gz` is glider
// sea046, mission 45, navigation ("gli"), yo 10. Empty fields / -1 when the
// name does not follow the pattern.
struct SeaExplorerName {
  std::string glider, mission, stream;  // stream: "gli", "pld1", "pld2", ...
  long yo = -1;
};
SeaExplorerName parseSeaExplorerName(std::string_view fileName);

// Rows -> table (not tidied). `complete` is false when the decompression
// stopped early: a last line without a line end is then cut short and
// skipped. A payload row with no sensor value (only the payload's copy of
// the navigation) is not a data row and is not counted. Rows with a bad time,
// a cell that is not a number or the wrong number of cells are skipped and
// reported. Throws InputError when the header is not a SeaExplorer table.
LogTable parseSeaExplorerTable(std::string_view text, bool complete, const std::string& file,
                               const SeaExplorerName& name, const ReadOptions& options, ReadReport& report);

// `dd/mm/yyyy HH:MM:SS[.f...]` -> seconds since 1970 UTC (also ISO 8601 and
// `dd.mm.yyyy ...`); false for anything else.
bool parseSeaExplorerTime(std::string_view text, double& epochSeconds);

}  // namespace auv::detail
