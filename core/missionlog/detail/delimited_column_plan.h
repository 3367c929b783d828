#pragma once
// How each header cell of a vendor text log is used: the time column (and a
// separate date column), the channel and unit of every other column from the
// column mapping or the channel aliases, and the columns left out.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "missionlog/column_mapping.h"
#include "missionlog/detail/delimited_layout.h"
#include "missionlog/log_table.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv::detail {

struct Plan {
  static constexpr int kIgnore = -1, kTime = -2, kDate = -3;
  std::vector<int> target;  // per field: table column index or one of the above
  std::size_t timeField = 0;
  std::optional<std::size_t> dateField;
  TimeFormat format = TimeFormat::kAuto;
  double timeScale = 1.0;  // numeric time unit -> s
  bool epochHint = false;  // the time unit says "epoch/timestamp"
  LogTable table;          // columns without values
};

// Notes ignored and renamed columns in `report`; throws InputError (naming
// the header line) when the time or date column the mapping names is not
// there, no column is a time, or the time column's unit is not a time.
Plan planColumns(const Layout& L, const ColumnMapping& m, const std::string& file, const ReadOptions& options,
                 ReadReport& report);

}  // namespace auv::detail
