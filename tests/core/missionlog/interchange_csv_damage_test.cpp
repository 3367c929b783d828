// Damaged interchange files: every fixture states what is wrong with it, and
// the test asserts exactly how many rows survive and what the report says.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/input_error.h"
#include "missionlog/interchange_csv.h"

namespace auv {
namespace {
std::string fixture(const std::string& name) {
  return std::string(AUV_TEST_DATA_DIR) + "/missionlog/" + name;
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

const ReadProblem& firstOf(const ReadReport& r, ReadProblemKind k) {
  for (const auto& p : r.problems)
    if (p.kind == k) return p;
  static const ReadProblem none;
  ADD_FAILURE() << "no problem of kind " << toString(k);
  return none;
}

// Every data line is accounted for: kept, skipped or merged.
void expectBalanced(const ReadReport& r) {
  EXPECT_EQ(r.data_lines, r.rows_kept + r.rows_skipped + r.rows_merged) << r.summary();
}

InputError readError(const std::string& name) {
  try {
    readInterchangeCsv(fixture(name));
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << name << " was accepted";
  return InputError("", "", "");
}
}  // namespace

TEST(InterchangeCsvDamage, UnparsableCellsSkipTheirRowAndNameTheCell) {
  ReadReport r;
  const MissionLog log = readInterchangeCsv(fixture("bad_cells.csv"), {}, r);
  EXPECT_EQ(log.time, (std::vector<double>{0, 3, 4, 7}));
  EXPECT_DOUBLE_EQ(log.channel("pitch").values[1], 7.0);  // " 7 " is fine
  EXPECT_DOUBLE_EQ(log.channel("pitch").values[2], 5.0);  // "+5" is fine
  EXPECT_EQ(r.rows_skipped, 4);
  EXPECT_EQ(r.count(ReadProblemKind::kNotANumber), 4);
  expectBalanced(r);
  const ReadProblem& p = firstOf(r, ReadProblemKind::kNotANumber);
  EXPECT_EQ(p.where.line, 3);
  EXPECT_EQ(p.where.column, 3);
  EXPECT_EQ(p.column, "depth");
  EXPECT_TRUE(contains(p.text(), "bad_cells.csv:3:3: depth: 'abc' is not a number; row skipped; "))
      << p.text();
  EXPECT_EQ(r.problems[1].where.line, 4);
  EXPECT_EQ(r.problems[1].where.column, 7);
  EXPECT_EQ(r.problems[1].column, "pitch");
}

TEST(InterchangeCsvDamage, WrongCellCountSkipsButTrailingEmptyCellsAreHarmless) {
  ReadReport r;
  const MissionLog log = readInterchangeCsv(fixture("bad_cell_count.csv"), {}, r);
  EXPECT_EQ(log.time, (std::vector<double>{0, 3, 4, 5}));
  EXPECT_EQ(r.count(ReadProblemKind::kWrongCellCount), 2);
  EXPECT_EQ(r.rows_skipped, 2);
  expectBalanced(r);
  EXPECT_EQ(r.problems[0].where.line, 3);
  EXPECT_TRUE(contains(r.problems[0].problem, "row has 2 cells, the header has 3")) << r.problems[0].problem;
  EXPECT_EQ(r.problems[1].where.line, 4);
  EXPECT_EQ(r.problems[1].where.column, 11);  // the surplus "9"
}

TEST(InterchangeCsvDamage, TimeOrderIsRepairedByDroppingTheFewestRows) {
  ReadReport r;
  const MissionLog log = readInterchangeCsv(fixture("bad_time_order.csv"), {}, r);
  // A backwards glitch (0.5 after 2) and a forward spike (1e6) cost one row
  // each; repeated times are merged.
  EXPECT_EQ(log.time, (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(r.count(ReadProblemKind::kTimeNotIncreasing), 2);
  EXPECT_EQ(r.rows_skipped, 2);
  EXPECT_EQ(r.rows_merged, 3);
  EXPECT_EQ(r.count(ReadProblemKind::kDuplicateTime), 3);
  EXPECT_EQ(r.count(ReadProblemKind::kConflictingDuplicate), 1);
  expectBalanced(r);
  const auto& depth = log.channel("depth").values;
  const auto& pitch = log.channel("pitch").values;
  EXPECT_DOUBLE_EQ(depth[4], 1.4);  // t = 4: depth from line 8 ...
  EXPECT_DOUBLE_EQ(pitch[4], 0.4);  // ... pitch filled in from line 9
  EXPECT_DOUBLE_EQ(depth[6], 1.6);  // conflict at t = 6: first value kept
  const ReadProblem& back = firstOf(r, ReadProblemKind::kTimeNotIncreasing);
  EXPECT_EQ(back.where.line, 5);
  EXPECT_TRUE(contains(back.problem, "time 0.5 s breaks the increasing order (previous kept row: line 4, 2 s)"))
      << back.problem;
  EXPECT_EQ(r.problems[1].where.line, 7);  // the spike
  const ReadProblem& conflict = firstOf(r, ReadProblemKind::kConflictingDuplicate);
  EXPECT_EQ(conflict.where.line, 13);
  EXPECT_EQ(conflict.column, "depth");
}

TEST(InterchangeCsvDamage, RowsWithoutTimeAreSkipped) {
  ReadReport r;
  const MissionLog log = readInterchangeCsv(fixture("bad_missing_time.csv"), {}, r);
  EXPECT_EQ(log.time, (std::vector<double>{0, 3}));
  EXPECT_EQ(r.count(ReadProblemKind::kMissingTime), 2);
  EXPECT_EQ(firstOf(r, ReadProblemKind::kMissingTime).where.line, 3);
  EXPECT_EQ(firstOf(r, ReadProblemKind::kMissingTime).column, "time");
  expectBalanced(r);
}

TEST(InterchangeCsvDamage, TruncatedLastLineIsSkipped) {
  ReadReport r;
  const MissionLog log = readInterchangeCsv(fixture("bad_truncated.csv"), {}, r);
  EXPECT_EQ(log.rowCount(), 2u);
  EXPECT_EQ(r.count(ReadProblemKind::kTruncatedLine), 1);
  const ReadProblem& p = firstOf(r, ReadProblemKind::kTruncatedLine);
  EXPECT_EQ(p.where.line, 5);
  EXPECT_EQ(p.where.column, 9);  // just after "2,1.2,0."
  EXPECT_TRUE(contains(p.problem, "cut short (3 cells, the header has 4)")) << p.problem;
  expectBalanced(r);
}

TEST(InterchangeCsvDamage, HugeAndInfiniteValuesAreBlankedNotKept) {
  ReadReport r;
  const MissionLog log = readInterchangeCsv(fixture("bad_huge.csv"), {}, r);
  EXPECT_EQ(log.time, (std::vector<double>{0, 1, 2, 3, 4, 5, 8}));  // 1e300 s and -inf s dropped
  const auto& depth = log.channel("depth").values;
  const auto& pitch = log.channel("pitch").values;
  const auto& sal = log.channel("salinity").values;
  EXPECT_TRUE(std::isnan(depth[1]));   // 1e400
  EXPECT_TRUE(std::isnan(pitch[2]));   // -1e309
  EXPECT_TRUE(std::isnan(pitch[3]));   // inf
  EXPECT_TRUE(std::isnan(sal[4]));     // NetCDF fill value 9.96921e36
  EXPECT_DOUBLE_EQ(sal[5], 0.0);       // 1e-400 underflows harmlessly
  EXPECT_DOUBLE_EQ(depth[2], 1.2);     // the rest of a row with a blanked cell is kept
  EXPECT_EQ(r.cells_blanked, 4);
  EXPECT_EQ(r.rows_skipped, 2);
  EXPECT_EQ(r.count(ReadProblemKind::kValueOutOfRange), 6);
  const ReadProblem& p = firstOf(r, ReadProblemKind::kValueOutOfRange);
  EXPECT_EQ(p.where.line, 3);
  EXPECT_EQ(p.column, "depth");
  EXPECT_TRUE(contains(p.problem, "'1e400' is infinite or beyond +-1e+30")) << p.problem;
  for (const auto& ch : log.channels)
    for (double v : ch.values) EXPECT_TRUE(std::isnan(v) || std::fabs(v) < 1e30);
  expectBalanced(r);
}

TEST(InterchangeCsvDamage, BinaryGarbageInTheMiddleCostsOnlyItsLines) {
  ReadReport r;
  const MissionLog log = readInterchangeCsv(fixture("bad_binary.csv"), {}, r);
  EXPECT_EQ(log.rowCount(), 10u);
  EXPECT_DOUBLE_EQ(log.channel("depth").values[9], 1.9);
  EXPECT_EQ(r.rows_skipped, 3);
  EXPECT_EQ(r.count(ReadProblemKind::kWrongCellCount), 2);
  EXPECT_EQ(r.count(ReadProblemKind::kNotANumber), 1);
  const ReadProblem& p = firstOf(r, ReadProblemKind::kNotANumber);
  EXPECT_EQ(p.where.line, 9);
  EXPECT_TRUE(contains(p.problem, "'\\x9c\\x003' is not a number")) << p.problem;  // printable
  expectBalanced(r);
}

TEST(InterchangeCsvDamage, OverlongLinesAreSkippedWithBoundedMemory) {
  ReadOptions o;
  o.block_bytes = 64;
  ReadReport r;
  const std::string text = "time [s],depth [m]\n0,1\n1," + std::string(500, '9') + "\n2,3\n";
  const MissionLog log = parseInterchangeCsv(text, "mem.csv", o, r);
  EXPECT_EQ(log.time, (std::vector<double>{0, 2}));
  EXPECT_EQ(r.count(ReadProblemKind::kOverlongLine), 1);
  EXPECT_EQ(firstOf(r, ReadProblemKind::kOverlongLine).where.line, 3);
  EXPECT_EQ(log.channel("depth").values[1], 3.0);
  // Before the header there is nothing to fall back on.
  EXPECT_THROW(parseInterchangeCsv(std::string(500, 'x') + "\ntime [s]\n0\n", "mem.csv", o, r), InputError);
}

TEST(InterchangeCsvDamage, ProblemListIsCappedButCountsAreComplete) {
  std::string text = "time [s],depth [m]\n";
  for (int i = 0; i < 100; ++i) text += std::to_string(i) + ",x\n";
  text += "100,1\n";
  ReadOptions o;
  o.max_problems_per_kind = 5;
  ReadReport r;
  const MissionLog log = parseInterchangeCsv(text, "mem.csv", o, r);
  EXPECT_EQ(log.rowCount(), 1u);
  EXPECT_EQ(r.count(ReadProblemKind::kNotANumber), 100);
  EXPECT_EQ(r.problems.size(), 5u);
  EXPECT_TRUE(contains(r.summary(), "100 x not a number")) << r.summary();
}

TEST(InterchangeCsvDamage, RefusesWhenNothingSensibleCanBeRead) {
  {
    const InputError e = readError("bad_no_time_column.csv");
    EXPECT_EQ(e.field(), "time");
    EXPECT_EQ(e.where().line, 3);
    EXPECT_TRUE(contains(e.what(), "no column named exactly `time` (found 'Time (s)')")) << e.what();
  }
  {
    const InputError e = readError("bad_semicolon.csv");
    EXPECT_TRUE(contains(e.what(), "comma-separated")) << e.what();
    EXPECT_TRUE(contains(e.what(), "';'")) << e.what();
  }
  {
    const InputError e = readError("bad_unit.csv");
    EXPECT_EQ(e.field(), "pitch");
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.where().column, 20);
    EXPECT_TRUE(contains(e.what(), "unit [m] cannot be converted to [deg]")) << e.what();
    EXPECT_TRUE(contains(e.what(), "rad")) << e.what();
  }
  {
    const InputError e = readError("bad_unknown_unit.csv");
    EXPECT_EQ(e.field(), "depth");
    EXPECT_EQ(e.where().column, 10);
    EXPECT_TRUE(contains(e.what(), "unit [furlong] cannot be converted to [m]")) << e.what();
  }
  EXPECT_TRUE(contains(readError("bad_header_only.csv").what(), "no usable data rows"));
  {
    const InputError e = readError("bad_no_usable_rows.csv");
    EXPECT_TRUE(contains(e.what(), "2 data lines, all skipped")) << e.what();
    EXPECT_TRUE(contains(e.what(), "bad_no_usable_rows.csv:2:1: time: 'a' is not a number")) << e.what();
  }
  EXPECT_TRUE(contains(readError("bad_empty.csv").what(), "the file is empty"));
  EXPECT_TRUE(contains(readError("bad_only_metadata.csv").what(), "no header line"));
  EXPECT_TRUE(contains(readError("bad_utf16.csv").what(), "UTF-16"));
  EXPECT_TRUE(contains(readError("bad_cr_only.csv").what(), "bare carriage return"));
  EXPECT_THROW(readInterchangeCsv(fixture("bad_random.bin")), InputError);
  EXPECT_THROW(readInterchangeCsv(fixture("no_such_file.csv")), InputError);
  EXPECT_THROW(readInterchangeCsv(std::string(AUV_TEST_DATA_DIR)), InputError);  // a directory
}

}  // namespace auv
