// A saved column mapping per vehicle: JSON load/save, refusal of bad
// mappings with the JSON path, and reading a file whose headers no alias
// knows (Norwegian HUGIN export, logger clock on local time).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "common/input_error.h"
#include "missionlog/column_mapping.h"
#include "missionlog/delimited_text_reader.h"
#include "missionlog/iso8601.h"

namespace auv {
namespace {
namespace fs = std::filesystem;

fs::path fixture(const std::string& name) { return fs::path(AUV_TEST_DATA_DIR) / "missionlog" / name; }
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string loadError(const std::string& name) {
  try {
    ColumnMapping::load(fixture(name));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << " was accepted";
  return {};
}

TEST(ColumnMapping, LoadsTheHuginMapping) {
  const ColumnMapping m = ColumnMapping::load(fixture("hugin1000_mapping.json"));
  EXPECT_EQ(m.vehicle, "hugin1000");
  EXPECT_EQ(m.delimiter, Delimiter::kSemicolon);
  EXPECT_EQ(m.decimal, DecimalMark::kComma);
  EXPECT_EQ(m.time.column, "Tid");
  EXPECT_EQ(m.time.format, TimeFormat::kDayMonthYear);
  ASSERT_TRUE(m.time.utc_offset_hours);
  EXPECT_EQ(*m.time.utc_offset_hours, 2.0);
  ASSERT_EQ(m.columns.size(), 3u);
  EXPECT_EQ(m.columns[0].channel, "depth_cmd");
  EXPECT_TRUE(m.columns[2].ignore);
  ASSERT_EQ(m.metadata.size(), 2u);
  EXPECT_TRUE((m.metadata[0].key == "logger" && m.metadata[0].value == "misc") ||
              (m.metadata[1].key == "logger" && m.metadata[1].value == "misc"));
}

TEST(ColumnMapping, ReadsAFileNoAliasKnows) {
  const ColumnMapping m = ColumnMapping::load(fixture("hugin1000_mapping.json"));
  ReadReport r;
  const MissionLog log = readDelimitedText(fixture("hugin_misc_no.txt"), m, {}, r);
  ASSERT_EQ(log.rowCount(), 3u);
  // 10:12:00 on a CEST clock (UTC + 2 h) is 08:12:00 UTC.
  EXPECT_EQ(*log.metadataValue("start"), "2026-05-14T08:12:00.000Z");
  EXPECT_EQ(log.time, (std::vector<double>{0, 2, 4}));
  EXPECT_EQ(log.channel("depth_cmd").values, (std::vector<double>{5.0, 5.0, 5.5}));
  EXPECT_EQ(log.channel("prop_rpm").values[2], 160.0);
  EXPECT_EQ(log.channels.size(), 2u);  // Status ignored as the mapping says
  EXPECT_EQ(*log.metadataValue("vehicle"), "hugin1000");
  EXPECT_EQ(*log.metadataValue("logger"), "misc");
  EXPECT_TRUE(r.clean()) << r.summary();  // the mapping states the zone: nothing assumed
}

TEST(ColumnMapping, WithoutTheMappingTheFileIsRefusedWithItsHeader) {
  ReadReport r;
  try {
    readDelimitedText(fixture("hugin_misc_no.txt"), {}, {}, r);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "no time column")) << e.what();
    EXPECT_TRUE(contains(e.what(), "Tid, \xC3\x98nsket dybde, Propell turtall, Status")) << e.what();
    EXPECT_TRUE(contains(e.what(), "column mapping")) << e.what();
  }
}

TEST(ColumnMapping, SaveAndLoadRoundTrip) {
  const ColumnMapping m = ColumnMapping::load(fixture("hugin1000_mapping.json"));
  const fs::path p = fs::temp_directory_path() / "auv_mapping_roundtrip.json";
  m.save(p);
  const ColumnMapping back = ColumnMapping::load(p);
  EXPECT_EQ(back.toJson(), m.toJson());
  EXPECT_EQ(back.columns.size(), m.columns.size());
  EXPECT_EQ(back.columns[1].header, "Propell turtall");
  EXPECT_EQ(*back.time.utc_offset_hours, 2.0);
  fs::remove(p);
  EXPECT_THROW(m.save(fs::path("/nonexistent-dir/x/mapping.json")), InputError);
}

TEST(ColumnMapping, BadMappingsNameTheField) {
  const std::string a = loadError("bad_mapping_unknown_key.json");
  EXPECT_TRUE(contains(a, "columns[0].chanel")) << a;
  EXPECT_TRUE(contains(a, "unknown field")) << a;
  const std::string b = loadError("bad_mapping_unit.json");
  EXPECT_TRUE(contains(b, "columns[0].unit")) << b;
  EXPECT_TRUE(contains(b, "cannot be converted to [m]")) << b;
  const std::string c = loadError("bad_mapping_syntax.json");
  EXPECT_TRUE(contains(c, "bad_mapping_syntax.json:4:")) << c;  // line of the missing comma
  EXPECT_TRUE(contains(loadError("does_not_exist.json"), "cannot open"));
  try {
    ColumnMapping::fromJson(R"({"column_mapping_version": 2})", "v2.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "column_mapping_version")) << e.what();
  }
  try {
    ColumnMapping::fromJson(R"({"column_mapping_version": 1, "delimiter": ",", "decimal": ","})", "dc.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "decimal comma cannot be used with a comma delimiter")) << e.what();
  }
  try {
    ColumnMapping::fromJson(R"({"column_mapping_version": 1, "columns": [{"header": "X", "channel": "a,b"}]})", "n.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "columns[0].channel")) << e.what();
  }
}

TEST(ColumnMapping, ScaleAndOffsetAndForcedUnits) {
  // A logger that counts roll port-down positive and writes depth in feet
  // under a header without a unit.
  const ColumnMapping m = ColumnMapping::fromJson(R"({
    "column_mapping_version": 1,
    "time": {"column": "t", "format": "seconds", "unit": "ms"},
    "columns": [
      {"header": "roll", "channel": "roll", "unit": "deg", "scale": -1},
      {"header": "D", "channel": "depth", "unit": "ft"},
      {"header": "temp", "channel": "temperature", "unit": "degC", "offset": -0.5}
    ]})", "m.json");
  ReadReport r;
  const MissionLog log = parseDelimitedText("t,roll,D,temp\n0,2.5,10,12.0\n500,-1.0,20,12.5\n", "x.csv", m, {}, r);
  EXPECT_EQ(log.time, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(log.channel("roll").values, (std::vector<double>{-2.5, 1.0}));
  EXPECT_DOUBLE_EQ(log.channel("depth").values[1], 20 * 0.3048);
  EXPECT_DOUBLE_EQ(log.channel("temperature").values[1], 12.0);
  EXPECT_TRUE(r.clean()) << r.summary();
}

TEST(ColumnMapping, SuggestedMappingReadsTheFileTheSameWay) {
  const ColumnMapping s = suggestColumnMapping(fixture("hugin_depth.txt"));
  EXPECT_EQ(s.delimiter, Delimiter::kSemicolon);
  EXPECT_EQ(s.decimal, DecimalMark::kComma);
  EXPECT_EQ(s.time.column, "Time");
  ASSERT_EQ(s.columns.size(), 3u);
  EXPECT_EQ(s.columns[0].header, "Depth(m)");
  EXPECT_EQ(s.columns[0].channel, "depth");
  EXPECT_EQ(s.columns[0].unit, "m");
  EXPECT_EQ(s.columns[2].channel, "pitch_cmd");
  EXPECT_EQ(s.columns[2].unit, "rad");
  // Through JSON and back, then reading with it.
  const ColumnMapping m = ColumnMapping::fromJson(s.toJson(), "suggested.json");
  ReadReport a, b;
  const MissionLog guessed = readDelimitedText(fixture("hugin_depth.txt"), {}, {}, a);
  const MissionLog mapped = readDelimitedText(fixture("hugin_depth.txt"), m, {}, b);
  EXPECT_EQ(guessed.time, mapped.time);
  for (const auto& c : guessed.channels) EXPECT_EQ(c.values, mapped.channel(c.name).values) << c.name;
}

}  // namespace
}  // namespace auv
