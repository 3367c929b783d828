#pragma once
// Rows of a LogTable as messages name them, and dropping rows from every
// column at once. A row is a 1-based line of a text file, or an index along
// a NetCDF dimension (LogTable::record_dimension), which has no line.
#include <cstddef>
#include <string>
#include <vector>

#include "common/input_error.h"
#include "missionlog/log_table.h"

namespace auv::detail {

// File and line of row i (line 0 for NetCDF records).
InputLocation rowLocation(const LogTable& t, std::size_t i);

// "sg_data_point[17]: " for NetCDF records, "" for text lines (their line is
// in the location).
std::string rowPrefix(const LogTable& t, std::size_t i);

// "line 12" or "sg_data_point[17]".
std::string rowName(const LogTable& t, std::size_t i);

// "12.5 s" for relative times, ISO 8601 for absolute ones.
std::string timeText(double t, bool epoch);

// Keeps the rows whose `keep` is set, in order, in time, row_where and every
// sampled column.
void keepRows(LogTable& t, const std::vector<char>& keep);

}  // namespace auv::detail
