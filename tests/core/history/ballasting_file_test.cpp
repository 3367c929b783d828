// The thesis 'ballasting' file (§5.5.2): read the two figures exactly as the
// thesis prints them, check them against the thesis's own tables, and round
// trip them through the history.
#include "history/ballasting_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <numeric>
#include <sstream>

#include "common/input_error.h"
#include "history/store.h"
#include "store_fixture.h"

namespace auv {
using namespace std::chrono;

namespace {
const std::string kThesis = std::string(AUV_SHARED_DIR) + "/seeds/hugin1000-ballast-thesis.txt";

std::vector<std::string> thesisLines() {
  std::ifstream in(kThesis);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// Lines from the one starting with `header` up to (not including) the first empty line.
std::vector<std::string> figureBlock(const std::string& header) {
  const auto lines = thesisLines();
  std::vector<std::string> block;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i] != header) continue;
    for (std::size_t j = i; j < lines.size() && !lines[j].empty(); ++j) block.push_back(lines[j]);
    break;
  }
  return block;
}

// Fig. 5.14 as printed: 3 header lines + 2 records of 3 lines, tab separated.
std::string figure514() {
  std::string text;
  for (const auto& l : figureBlock("Config\tDate\tType\tArea")) text += l + "\n";
  return text;
}

// Fig. 7.9 as extracted from the PDF: each record's two lines were merged
// column by column ("sys-0-0 1565.2" = Config of line 1, TotalWeight of line
// 2), a space was inserted after every '.', and the second header line was
// lost. Undo exactly these three things and nothing else.
std::string figure79() {
  const auto block = figureBlock("Config\tDate\tType\tArea\tSalinity\tTemperature");
  if (block.empty()) return "";
  std::string text = block[0] + "\nTotalWeight\tAddedWeight\tDepthDeviation\tPitchDeviation\tRollDeviation\n";
  for (std::size_t i = 1; i < block.size(); ++i) {
    std::string line1, line2, cell;
    std::istringstream cells(block[i]);
    while (std::getline(cells, cell, '\t')) {
      for (std::size_t p; (p = cell.find(". ")) != std::string::npos;) cell.erase(p + 1, 1);
      const auto space = cell.find(' ');
      if (!line1.empty()) line1 += '\t';
      line1 += cell.substr(0, space);
      if (space == std::string::npos) continue;
      if (!line2.empty()) line2 += '\t';
      line2 += cell.substr(space + 1);
    }
    text += line1 + "\n" + line2 + "\n";
  }
  return text;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

class BallastingTest : public test::StoreTest {
 protected:
  void SetUp() override {
    if (figureBlock("Config\tDate\tType\tArea").empty()) GTEST_SKIP() << "thesis seed not found: " << kThesis;
  }
};
}  // namespace

TEST_F(BallastingTest, Figure514ReadsAsPrinted) {
  const auto f = parseBallastingFile(figure514(), "fig5.14");
  EXPECT_TRUE(f.warnings.empty());
  ASSERT_EQ(f.rows.size(), 2u);
  const auto& first = f.rows[0];
  EXPECT_EQ(first.config_id, "1-2-3");
  EXPECT_EQ(first.at, makeUtc(2014, 4, 4, 15, 28));
  EXPECT_EQ(first.vehicle_type, "HUGIN1000");
  EXPECT_EQ(first.area, "Horten");
  EXPECT_EQ(*first.salinity_psu, 35.0);
  EXPECT_EQ(*first.temperature_degC, 4.0);
  EXPECT_EQ(first.added_kg, (std::vector<double>{0, 0, 19.2, 19.2}));
  EXPECT_FALSE(first.depth_deviation_m || first.pitch_deviation_deg || first.roll_deviation_deg);
  EXPECT_EQ(first.line, 4);
  const auto& second = f.rows[1];
  EXPECT_EQ(second.at, makeUtc(2014, 4, 4, 15, 34));
  EXPECT_EQ(*second.temperature_degC, 6.545581);  // printed 6.545581e+00
  EXPECT_EQ(*second.salinity_psu, 34.4975);
  EXPECT_EQ(*second.depth_deviation_m, 2.34218);
  EXPECT_EQ(*second.pitch_deviation_deg, 0.59959);
  EXPECT_EQ(*second.roll_deviation_deg, 0.73636);
  // TotalWeight includes AddedWeight: 1536.4 - 38.4 = 1498 kg, the crane
  // weight of Table 3.1 / Table F.3.
  for (const auto& r : f.rows) EXPECT_NEAR(*r.total_weight_kg - sum(r.added_kg), 1498.0, 1e-9);
}

TEST_F(BallastingTest, Figure79AgreesWithTableF3) {
  const auto f = parseBallastingFile(figure79(), "fig7.9");
  EXPECT_TRUE(f.warnings.empty());
  ASSERT_EQ(f.rows.size(), 3u);
  // Table F.3, "First mission" column: 4 degC, 35, errors Unknown.
  EXPECT_EQ(*f.rows[0].temperature_degC, 4.0);
  EXPECT_EQ(*f.rows[0].salinity_psu, 35.0);
  EXPECT_FALSE(f.rows[0].depth_deviation_m);
  // Table F.3, "Post mission" column: 6.545581, 34.49, 8.7594, -0.59959, 0.73636.
  const auto& post = f.rows[1];
  EXPECT_EQ(*post.temperature_degC, 6.545581);
  EXPECT_NEAR(*post.salinity_psu, 34.49, 0.01);
  EXPECT_EQ(*post.depth_deviation_m, 8.7594);
  EXPECT_EQ(*post.pitch_deviation_deg, -0.59959);
  EXPECT_EQ(*post.roll_deviation_deg, 0.73636);
  EXPECT_EQ(post.at, makeUtc(2014, 5, 19, 20, 32));
  // Every row: total = 1498.0 kg (Table F.3) + the added weight.
  for (const auto& r : f.rows) EXPECT_NEAR(*r.total_weight_kg - sum(r.added_kg), 1498.0, 1e-9);
  // The pre-mission row added one 4.8 kg piece in total (1570 - 1565.2).
  EXPECT_NEAR(sum(f.rows[2].added_kg) - sum(f.rows[1].added_kg), 4.8, 1e-9);
  EXPECT_EQ(f.rows[2].added_kg, (std::vector<double>{9.6, 10.8, 25.2, 26.4}));
}

TEST_F(BallastingTest, Figure514RoundTripsThroughTheHistory) {
  const std::string printed = figure514();
  HistoryStore store(db_path);
  const auto imp = importBallastingFile(store, parseBallastingFile(printed, "fig5.14"), "fig5.14");
  EXPECT_EQ(imp.rows_imported, 2);
  const std::string exported = exportBallastingFile(store, "1-2-3");
  // Byte-identical except that numbers are written shortest-exact, not %e.
  std::string expected = printed;
  expected.replace(expected.find("6.545581e+00"), 12, "6.545581");
  EXPECT_EQ(exported, expected);
  // And the export is a fixpoint: import it elsewhere, export again.
  HistoryStore other(dir.file("other.db"));
  importBallastingFile(other, parseBallastingFile(exported, "export"), "export");
  EXPECT_EQ(exportBallastingFile(other, "1-2-3"), exported);
  // Importing the same file again adds nothing.
  const auto again = importBallastingFile(store, parseBallastingFile(printed, "fig5.14"), "fig5.14");
  EXPECT_EQ(again.rows_imported, 0);
  EXPECT_EQ(again.rows_already_present, 2);
  EXPECT_EQ(store.history("1-2-3").size(), 5u);  // 2 water, 1 analysis, 2 installed
}

TEST_F(BallastingTest, Figure79ImportKeepsTheTemperatureAge) {
  HistoryStore store(db_path);
  const auto file = parseBallastingFile(figure79(), "fig7.9");
  importBallastingFile(store, file, "fig7.9");
  int water = 0, analysis = 0, inst = 0;
  for (const auto& e : store.history("sys-0-0")) {
    water += e.kind == EventKind::kWater;
    analysis += e.kind == EventKind::kAnalysis;
    inst += e.kind == EventKind::kInstalled;
  }
  // The pre-mission row repeats the post-mission water and errors: not new facts.
  EXPECT_EQ(water, 2);
  EXPECT_EQ(analysis, 1);
  EXPECT_EQ(inst, 3);
  const auto s = store.lastState("sys-0-0", makeUtc(2014, 5, 20, 12, 19));
  ASSERT_TRUE(s && s->last_temperature && s->installed && s->last_analysis);
  EXPECT_EQ(s->last_temperature->measured_at, makeUtc(2014, 5, 19, 20, 32));
  EXPECT_EQ(*s->temperature_age, hours{15} + minutes{47});
  EXPECT_FALSE(s->temperature_stale);
  EXPECT_DOUBLE_EQ(*s->installed->total_mass_kg, 1570.0);
  EXPECT_EQ(s->installed->points[1].name, "fore_port");
  EXPECT_DOUBLE_EQ(s->installed->points[1].mass_kg, 10.8);
  EXPECT_DOUBLE_EQ(s->last_analysis->result[kDepthDeviationKey].get<double>(), 8.7594);
  EXPECT_TRUE(store.lastState("sys-0-0", makeUtc(2014, 6, 19, 20, 33))->temperature_stale);
  // Export gives back the three printed rows.
  const auto back = parseBallastingFile(exportBallastingFile(store, "sys-0-0"), "export").rows;
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back[i].at, file.rows[i].at);
    EXPECT_EQ(back[i].salinity_psu, file.rows[i].salinity_psu);
    EXPECT_EQ(back[i].temperature_degC, file.rows[i].temperature_degC);
    EXPECT_EQ(back[i].total_weight_kg, file.rows[i].total_weight_kg);
    EXPECT_EQ(back[i].added_kg, file.rows[i].added_kg);
    EXPECT_EQ(back[i].depth_deviation_m, file.rows[i].depth_deviation_m);
    EXPECT_EQ(back[i].pitch_deviation_deg, file.rows[i].pitch_deviation_deg);
    EXPECT_EQ(back[i].roll_deviation_deg, file.rows[i].roll_deviation_deg);
  }
}

TEST_F(BallastingTest, OneLinePerRecordIsTheSameFile) {
  // The 11 columns on one line each (how a wide editor shows it) parse the same.
  std::string text = figure514();
  std::string one_line;
  int newlines = 0;
  for (char c : text) {
    if (c == '\n' && ++newlines % 3 != 0) c = '\t';
    one_line += c;
  }
  const auto a = parseBallastingFile(text, "a").rows;
  const auto b = parseBallastingFile(one_line, "b").rows;
  ASSERT_EQ(b.size(), a.size());
  EXPECT_EQ(b[1].roll_deviation_deg, a[1].roll_deviation_deg);
  EXPECT_EQ(b[1].line, 3);
}

TEST(BallastingFileErrors, HeaderAndTruncationNameFileLineColumn) {
  try {
    parseBallastingFile("Config Date Type Area\n", "cfg/ballasting");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "cfg/ballasting");
    EXPECT_EQ(e.where().line, 1);
    EXPECT_NE(std::string(e.what()).find("separated by tabs"), std::string::npos);
  }
  const std::string header =
      "Config\tDate\tType\tArea\nSalinity\tTemperature\tTotalWeight\tAddedWeight\n"
      "DepthDeviation\tPitchDeviation\tRollDeviation\t\n";
  try {
    parseBallastingFile(header + "1-2-3\t4.4.2014-15:28\tHUGIN1000\tHorten\n35\t4\t1536.4\t0:0:0:0\n"
                        "Unknown\tUnknown\n", "b");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(std::string(e.what()).find("10 of 11 fields"), std::string::npos) << e.what();
  }
}

TEST(BallastingFileErrors, BadRecordIsSkippedWithItsPosition) {
  const std::string text =
      "Config\tDate\tType\tArea\tSalinity\tTemperature\tTotalWeight\tAddedWeight\t"
      "DepthDeviation\tPitchDeviation\tRollDeviation\n"
      "1-2-3\t31.2.2014-10:00\tHUGIN1000\tHorten\t35\t4\t1498\t0:0:0:0\tUnknown\tUnknown\tUnknown\n"
      "1-2-3\t1.3.2014-10:00\tHUGIN1000\tHorten\t35\t4\t1498\t0:0::0\tUnknown\tUnknown\tUnknown\n"
      "1-2-3\t2.3.2014-10:00\tHUGIN1000\tHorten\t35\t4\t1498\t0:0:0:0\tUnknown\tUnknown\tUnknown\n"
      "1-2-3\t3.3.2014-10:00\tHUGIN1000\tHorten\t35\t4\t1498\t0:0:0:0\t0,5\tUnknown\tUnknown\n";
  const auto f = parseBallastingFile(text, "b.txt");
  ASSERT_EQ(f.rows.size(), 1u);
  EXPECT_EQ(f.rows[0].at, makeUtc(2014, 3, 2, 10));
  ASSERT_EQ(f.warnings.size(), 3u);
  EXPECT_EQ(f.warnings[0].rfind("b.txt:2:7: Date: ", 0), 0u) << f.warnings[0];
  EXPECT_NE(f.warnings[1].find("b.txt:3:"), std::string::npos) << f.warnings[1];
  EXPECT_NE(f.warnings[1].find("AddedWeight"), std::string::npos) << f.warnings[1];
  EXPECT_NE(f.warnings[2].find("DepthDeviation: '0,5' is not a number"), std::string::npos)
      << f.warnings[2];
}

TEST_F(BallastingTest, ImportIsAllOrNothing) {
  HistoryStore store(db_path);
  store.addConfiguration(test::hugin("7-7-7", makeUtc(2014, 1, 1)));
  const std::string text =
      "Config\tDate\tType\tArea\tSalinity\tTemperature\tTotalWeight\tAddedWeight\t"
      "DepthDeviation\tPitchDeviation\tRollDeviation\n"
      "1-2-3\t1.3.2014-10:00\tHUGIN1000\tHorten\t35\t4\t1498\t0:0:0:0\tUnknown\tUnknown\tUnknown\n"
      "7-7-7\t2.3.2014-10:00\tSLOCUM\tHalifax\t31\t3\t52\t0.1:0.1\tUnknown\tUnknown\tUnknown\n";
  try {
    importBallastingFile(store, parseBallastingFile(text, "mixed.txt"), "mixed.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(std::string(e.what()).find("HUGIN1000 in the history"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(store.configuration("1-2-3"));  // the good first row was rolled back too
  EXPECT_EQ(store.integrityCheck(), "ok");
}

TEST_F(BallastingTest, NativeHistoryExportsOneRowPerMinute) {
  HistoryStore store(db_path);
  const TimePoint t0 = makeUtc(2024, 6, 3, 9, 0, 10);
  store.addConfiguration(test::hugin("05-06-07", t0));
  store.addWaterCondition("05-06-07", test::water(t0, 7.5, 33.0));  // before any install: carried
  auto s = test::installed(t0 + minutes{60}, 4.8, 4.8, 0, 1.2);
  s.total_mass_kg = 1508.8;
  store.addInstalledState("05-06-07", s);
  store.addWaterCondition("05-06-07", test::water(t0 + minutes{60} + seconds{30}, 7.0, 33.5));
  Recommendation r;  // not part of the thesis file
  r.at = t0 + minutes{90};
  r.policy = "exact";
  store.addRecommendation("05-06-07", r);
  AnalysisResult a;
  a.at = t0 + minutes{120};
  a.result = {{kDepthDeviationKey, 0.4}, {kPitchDeviationKey, -0.2}, {kRollDeviationKey, 0.05}};
  store.addAnalysisResult("05-06-07", a);
  const auto rows = ballastingRowsFromHistory(store, "05-06-07");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at, makeUtc(2024, 6, 3, 10, 0));
  EXPECT_EQ(*rows[0].temperature_degC, 7.0);  // both saves of that minute applied
  EXPECT_EQ(rows[0].added_kg, (std::vector<double>{4.8, 4.8, 0, 1.2}));
  EXPECT_FALSE(rows[0].depth_deviation_m);
  EXPECT_EQ(rows[1].at, makeUtc(2024, 6, 3, 11, 0));
  EXPECT_EQ(*rows[1].depth_deviation_m, 0.4);
  EXPECT_EQ(*rows[1].total_weight_kg, 1508.8);
  EXPECT_NE(formatBallastingFile(rows).find("05-06-07\t3.6.2024-11:00\tHUGIN1000\tHorten\n"
                                            "33.5\t7\t1508.8\t4.8:4.8:0:1.2\n0.4\t-0.2\t0.05\t\n"),
            std::string::npos);
}

}  // namespace auv
