#include "history/export.h"

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "history/sha256.h"
#include "store_fixture.h"

namespace auv {
using namespace std::chrono;

namespace {
// A small RFC 4180 reader, written independently of the exporter.
std::vector<std::vector<std::string>> readCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field);
      field.clear();
    } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
      rows.back().push_back(field);
      field.clear();
      rows.emplace_back();
      ++i;
    } else {
      field += c;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

class ExportTest : public test::StoreTest {
 protected:
  void fill(HistoryStore& store) {
    const TimePoint t0 = makeUtc(2014, 5, 19, 17, 9);
    auto c = test::hugin("sys-0-0", t0);
    c.payload_note = "note with, comma and \"quotes\"\nand a line break";
    store.addConfiguration(c);
    Weighing w;
    w.at = t0;
    w.method = WeighingMethod::kTank;
    w.inputs = {{"bow_g", 550}, {"aft_g", 490}};  // Slocum App. C spring scales
    store.addWeighing("sys-0-0", w);
    store.addWaterCondition("sys-0-0", test::water(t0, 4, 35));
    auto s = test::installed(t0 + minutes{1}, 9.6, 9.6, 24, 24);
    s.total_mass_kg = 1565.2;
    store.addInstalledState("sys-0-0", s);
    Mission m;
    m.imported_at = t0 + hours{3};
    m.file_path = "/logs/mission, 1.txt";
    m.sha256 = sha256Hex("log");
    AnalysisResult a;
    a.at = m.imported_at;
    a.result = {{"depth_deviation_m", 8.7594}};
    store.savePostMission("sys-0-0", m, a, test::water(m.imported_at, 6.545581, 34.4975, "mission"));
    Recommendation r;
    r.at = m.imported_at + minutes{5};
    r.policy = "half";
    r.recommendation = {{"points", {{{"name", "fore_port"}, {"add_kg", 1.2}}}}};
    r.accepted = true;
    store.addRecommendation("sys-0-0", r);
  }
};
}  // namespace

TEST_F(ExportTest, JsonHoldsEveryRecordInTimeOrder) {
  HistoryStore store(db_path);
  fill(store);
  const auto j = exportHistoryJson(store, "sys-0-0");
  EXPECT_EQ(j["format"], "auvballast-history");
  EXPECT_EQ(j["schema_version"], 5);
  EXPECT_EQ(j["configuration"]["payload_note"].get<std::string>().find("line break") != std::string::npos, true);
  const auto& ev = j["events"];
  ASSERT_EQ(ev.size(), 7u);
  const std::vector<std::string> kinds = {"weighing", "water",    "installed",     "water",
                                          "mission",  "analysis", "recommendation"};
  for (std::size_t i = 0; i < kinds.size(); ++i) EXPECT_EQ(ev[i]["kind"], kinds[i]) << i;
  for (std::size_t i = 1; i < ev.size(); ++i)
    EXPECT_LE(ev[i - 1]["at"].get<std::string>(), ev[i]["at"].get<std::string>());
  EXPECT_EQ(ev[0]["record"]["method"], "tank");
  EXPECT_EQ(ev[2]["record"]["points"][2]["mass_kg"], 24.0);
  EXPECT_EQ(ev[3]["record"]["temperature_degC"], 6.545581);
  EXPECT_EQ(ev[5]["record"]["mission_id"], ev[4]["id"]);
  EXPECT_EQ(ev[6]["record"]["accepted"], true);
  // The JSON text parses back to the same document.
  EXPECT_EQ(nlohmann::json::parse(j.dump()), j);
}

TEST_F(ExportTest, CsvIsRfc4180AndCarriesTheWholeRecord) {
  HistoryStore store(db_path);
  fill(store);
  const std::string csv = exportHistoryCsv(store, "sys-0-0");
  const auto rows = readCsv(csv);
  ASSERT_EQ(rows.size(), 8u);  // header + 7 records
  for (const auto& r : rows) ASSERT_EQ(r.size(), 16u);
  EXPECT_EQ(rows[0][0], "timestamp");
  EXPECT_EQ(rows[0][15], "record_json");
  EXPECT_EQ(rows[1][0], "2014-05-19T17:09:00Z");
  EXPECT_EQ(rows[1][10], "tank");
  EXPECT_EQ(rows[3][8], "fore_starboard=9.6;fore_port=9.6;aft_starboard=24;aft_port=24");
  EXPECT_EQ(rows[3][9], "1565.2");
  EXPECT_EQ(rows[4][4], "6.545581");
  EXPECT_EQ(rows[4][5], "34.4975");
  EXPECT_EQ(rows[5][13], "/logs/mission, 1.txt");  // comma survived quoting
  EXPECT_EQ(rows[5][14], sha256Hex("log"));
  EXPECT_EQ(rows[7][11], "half");
  EXPECT_EQ(rows[7][12], "1");
  // The last column is the complete record: it equals the JSON export's.
  const auto j = exportHistoryJson(store, "sys-0-0");
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_EQ(nlohmann::json::parse(rows[i][15]), j["events"][i - 1]["record"]) << i;
  EXPECT_THROW(exportHistoryCsv(store, "0-0-0"), InputError);
}

}  // namespace auv
