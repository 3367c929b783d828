#pragma once
// The rows of one vendor text log into a LogTable: the layout and column plan
// are decided from the head of the file, then every line is handed in (in
// blocks, by forEachLine). Rows with a bad time, a bad number or the wrong
// cell count are skipped and reported; time stamps are read in the format the
// mapping names or the first row shows.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/column_mapping.h"
#include "missionlog/detail/delimited_column_plan.h"
#include "missionlog/detail/delimited_layout.h"
#include "missionlog/detail/line_cells.h"
#include "missionlog/log_table.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"
#include "missionlog/text_lines.h"

namespace auv::detail {

class TextTableReader {
 public:
  TextTableReader(std::string file, const ColumnMapping& m, const ReadOptions& o, ReadReport& r)
      : file_(std::move(file)), map_(m), opt_(o), rep_(r) {}

  // Sniffs and plans from `head`; throws InputError when the layout is not usable.
  void prepare(std::string_view head, bool complete);
  // The file size, to reserve the rows once (call before prepare).
  void setSizeHint(std::uint64_t n) { sizeHint_ = n; }

  // Every line of the file, for forEachLine.
  bool line(std::string_view text, LineFlag flag);
  // The table read, not yet tidied; throws InputError when no row is usable.
  LogTable finish();
  const Layout& layout() const { return layout_; }
  const Plan& plan() const { return plan_; }

 private:
  void problem(ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix);
  void skip(ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix);
  bool parseTime(std::string_view cell, std::string_view dateCell, double& t);
  void detectFormat(std::string_view cell);

  std::string file_;
  const ColumnMapping& map_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  std::uint64_t sizeHint_ = 0;
  std::size_t expectedRows_ = 0;
  Layout layout_;
  Plan plan_;
  std::size_t nFields_ = 0;
  long long line_ = 0;
  std::vector<Cell> cells_;
  std::vector<double> row_;
  bool zoneNoted_ = false;
  double todDay_ = 0.0, lastTod_ = -1.0;
};

}  // namespace auv::detail
