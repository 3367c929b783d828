#pragma once
// The data rows of an interchange CSV. Two paths per row: a tight fast path
// (the number parser straight on the read buffer, no allocation, no field
// pre-scan) that accepts only perfectly regular rows, and a careful slow path
// that re-reads any row the fast path did not like, decides what is wrong and
// reports it.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/detail/interchange_header.h"
#include "missionlog/detail/line_cells.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv::detail {

class InterchangeRowReader {
 public:
  // `line` is the number of the header line; `sizeHint` the file size, to
  // reserve the columns once.
  InterchangeRowReader(std::string file, InterchangeHeader header, long long line, std::uint64_t sizeHint,
                       const ReadOptions& options, ReadReport& report);

  // Complete lines: [b, e) with e[-1] == '\n'.
  void lines(const char* b, const char* e);
  // The last line of the file when it has no line end.
  void finalLine(std::string_view line);
  // A line longer than the read block, already skipped by the driver.
  void overlongLine();

  long long line() const { return line_; }
  // What was read: per header column its values in the file's unit (NaN = not
  // sampled; ISO times as epoch seconds), and the line of each row.
  InterchangeHeader& header() { return header_; }
  std::vector<std::vector<double>>& data() { return data_; }
  std::vector<long long>& rowLines() { return row_line_; }

 private:
  void problem(ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix);
  void reserveRows(const char* b, const char* e);
  void dataLines(const char* p, const char* end);
  void slowRow(std::string_view line, bool finalNoNewline);
  void commitRow() {
    const std::size_t n = header_.columns.size();
    for (std::size_t c = 0; c < n; ++c) data_[c].push_back(row_[c]);
    row_line_.push_back(line_);
  }

  std::string file_;
  InterchangeHeader header_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  std::uint64_t size_hint_;
  long long line_;
  bool reserved_ = false;
  bool iso_no_zone_accepted_ = false;
  std::vector<std::vector<double>> data_;
  std::vector<long long> row_line_;
  std::vector<double> row_;
  std::vector<Cell> cells_;
};

}  // namespace auv::detail
