#include <gtest/gtest.h>

#include "common/input_error.h"
#include "history/sha256.h"
#include "history/transaction.h"
#include "store_fixture.h"

namespace auv {
using namespace std::chrono;
using test::hugin;
using test::installed;
using test::water;

class HistoryStoreTest : public test::StoreTest {};

TEST_F(HistoryStoreTest, NewFileIsMigratedWithDurabilitySettings) {
  HistoryStore store(db_path);
  EXPECT_EQ(store.schemaVersion(), latestSchemaVersion());
  EXPECT_EQ(store.schemaVersion(), 5);
  Database& db = store.database();
  EXPECT_EQ(db.queryText("PRAGMA journal_mode"), "wal");
  EXPECT_EQ(db.queryInt("PRAGMA foreign_keys"), 1);
  EXPECT_EQ(db.queryInt("PRAGMA synchronous"), 2);  // 2 = FULL
  EXPECT_EQ(db.queryInt("PRAGMA busy_timeout"), 5000);
  EXPECT_EQ(store.integrityCheck(), "ok");
  for (const char* table : {"vehicles", "configurations", "weighings", "water_conditions",
                            "missions", "analysis_results", "recommendations", "installed_states"})
    EXPECT_EQ(db.queryInt(std::string("SELECT count(*) FROM sqlite_schema WHERE name = '") + table +
                          "'"),
              1)
        << table;
}

TEST_F(HistoryStoreTest, RecordsRoundTripThroughTheFile) {
  const TimePoint t0 = makeUtc(2014, 5, 19, 17, 9);
  {
    HistoryStore store(db_path);
    store.addConfiguration(hugin("sys-0-0", t0));
    Weighing w;
    w.at = t0;
    w.method = WeighingMethod::kCrane;
    w.inputs = {{"scales_kg", {404.5, 384.5, 364.5, 344.5}}, {"total_kg", 1498.0}};
    w.results = {{"mass_kg", 1498.0}};
    store.addWeighing("sys-0-0", w);
    InstalledState s = installed(t0 + minutes{5}, 9.6, 9.6, 24.0, 24.0);
    s.points[2].pieces_kg = {4.8, 4.8, 4.8, 4.8, 4.8};
    s.total_mass_kg = 1565.2;
    store.addInstalledState("sys-0-0", s);
  }
  HistoryStore store(db_path);  // reopened: everything came from the file
  const auto c = store.configuration("SYS-0-0");  // IDs compare case-insensitively
  ASSERT_TRUE(c);
  EXPECT_EQ(c->config_id, "sys-0-0");
  EXPECT_EQ(c->vehicle_key, "hugin1000");
  EXPECT_EQ(c->created_at, t0);
  const auto events = store.history("sys-0-0");
  ASSERT_EQ(events.size(), 2u);
  const auto& w = std::get<Weighing>(events[0].record);
  EXPECT_EQ(w.inputs["scales_kg"][1].get<double>(), 384.5);
  const auto& s = std::get<InstalledState>(events[1].record);
  ASSERT_EQ(s.points.size(), 4u);
  EXPECT_EQ(s.points[2].name, "aft_starboard");
  EXPECT_EQ(s.points[2].pieces_kg.size(), 5u);
  EXPECT_DOUBLE_EQ(*s.total_mass_kg, 1565.2);
}

TEST_F(HistoryStoreTest, AcceptedModelTermsRoundTripAndTheLatestWins) {
  const TimePoint t0 = makeUtc(2026, 5, 19, 17, 9);
  {
    HistoryStore store(db_path);
    store.addConfiguration(hugin("01-02-03", t0));
    ModelTerms m;
    m.at = t0;
    m.model = {{"log", "a.csv"},
               {"accepted", {{{"id", "hull_compressibility"}, {"value", 4.7e-6}}}},
               {"profile", {{"id", "hugin1000"}, {"hull", {{"compressibility_per_dbar", 4.7e-6}}}}}};
    store.addModelTerms("01-02-03", m);
    m.at = t0 + minutes{60};
    m.model["profile"]["hull"]["compressibility_per_dbar"] = 5.1e-6;
    store.addModelTerms("01-02-03", m);
    ModelTerms bad;
    bad.at = t0;
    EXPECT_THROW(store.addModelTerms("01-02-03", bad), InputError);  // no profile: refused, nothing written
  }
  HistoryStore store(db_path);
  EXPECT_EQ(store.database().queryInt("SELECT count(*) FROM model_terms"), 2);
  const auto latest = store.latestModelTerms("01-02-03", makeUtc(2030, 1, 1));
  ASSERT_TRUE(latest);
  EXPECT_DOUBLE_EQ(latest->model["profile"]["hull"]["compressibility_per_dbar"].get<double>(), 5.1e-6);
  const auto earlier = store.latestModelTerms("01-02-03", t0 + minutes{30});
  ASSERT_TRUE(earlier);
  EXPECT_DOUBLE_EQ(earlier->model["profile"]["hull"]["compressibility_per_dbar"].get<double>(), 4.7e-6);
  EXPECT_FALSE(store.latestModelTerms("01-02-03", t0 - minutes{1}));
  // Part of the configuration's record, in time order.
  int n = 0;
  for (const HistoryEvent& e : store.history("01-02-03")) {
    if (e.kind != EventKind::kModelTerms) continue;
    ++n;
    EXPECT_EQ(toJson(e)["kind"], "model_terms");
    EXPECT_TRUE(toJson(e)["record"]["model"].contains("profile"));
  }
  EXPECT_EQ(n, 2);
}

TEST_F(HistoryStoreTest, LastStateReportsPiecesErrorsAndTemperatureAge) {
  HistoryStore store(db_path);
  const TimePoint t0 = makeUtc(2024, 1, 31, 8);
  store.addConfiguration(hugin("01-02-03", t0));
  store.addInstalledState("01-02-03", installed(t0, 0, 0, 19.2, 19.2));
  store.addWaterCondition("01-02-03", water(t0, 4.0, 35.0, "operator"));
  Mission m;
  m.imported_at = t0 + days{2};
  m.file_path = "/data/mission1.log";
  m.sha256 = sha256Hex("mission 1 log");
  AnalysisResult a;
  a.at = m.imported_at;
  a.result = {{"net_buoyancy_kg", 2.4}, {"pitch_deg", -0.6}};
  const auto ids = store.savePostMission("01-02-03", m, a, water(m.imported_at, 6.5, 34.5, "mission"));
  // A later analysis not tied to a mission must not hide the last mission's errors.
  AnalysisResult what_if;
  what_if.at = m.imported_at + hours{1};
  what_if.result = {{"scenario", "what-if"}};
  store.addAnalysisResult("01-02-03", what_if);
  store.addInstalledState("01-02-03", installed(t0 + days{3}, 1.2, 0, 19.2, 20.4));

  const auto s = store.lastState("01-02-03", makeUtc(2024, 2, 29, 12));
  ASSERT_TRUE(s);
  ASSERT_TRUE(s->installed);
  EXPECT_DOUBLE_EQ(s->installed->points[3].mass_kg, 20.4);
  ASSERT_TRUE(s->last_mission);
  EXPECT_EQ(s->last_mission->id, ids.mission);
  ASSERT_TRUE(s->last_analysis);
  EXPECT_EQ(s->last_analysis->id, ids.analysis);
  EXPECT_DOUBLE_EQ(s->last_analysis->result["net_buoyancy_kg"].get<double>(), 2.4);
  ASSERT_TRUE(s->last_temperature);
  EXPECT_DOUBLE_EQ(*s->last_temperature->temperature_degC, 6.5);
  // Measured 2024-02-02 08:00, asked 2024-02-29 12:00: 27 d 4 h.
  EXPECT_EQ(*s->temperature_age, days{27} + hours{4});
  EXPECT_FALSE(s->temperature_stale);
  // 2024-03-02 08:00 is exactly one month; one second later it is stale.
  EXPECT_FALSE(store.lastState("01-02-03", makeUtc(2024, 3, 2, 8))->temperature_stale);
  EXPECT_TRUE(store.lastState("01-02-03", makeUtc(2024, 3, 2, 8, 0, 1))->temperature_stale);
  EXPECT_FALSE(store.lastState("99-99-99", t0));
}

TEST_F(HistoryStoreTest, HistoryIsInTimeOrderWhateverTheSaveOrder) {
  HistoryStore store(db_path);
  const TimePoint t0 = makeUtc(2014, 4, 4, 15, 28);
  store.addConfiguration(hugin("1-2-3", t0));
  store.addInstalledState("1-2-3", installed(t0 + hours{3}, 0, 0, 0, 0));
  store.addWaterCondition("1-2-3", water(t0 + hours{1}, 5, 35));
  Recommendation r;
  r.at = t0 + hours{2};
  r.policy = "exact";
  const RecordId rec = store.addRecommendation("1-2-3", r);
  store.setRecommendationAccepted(rec, true);
  store.addWaterCondition("1-2-3", water(t0 + hours{3}, 6, 35));  // same second as installed
  const auto ev = store.history("1-2-3");
  ASSERT_EQ(ev.size(), 4u);
  EXPECT_EQ(ev[0].kind, EventKind::kWater);
  EXPECT_EQ(ev[1].kind, EventKind::kRecommendation);
  EXPECT_TRUE(std::get<Recommendation>(ev[1].record).accepted);
  EXPECT_EQ(ev[2].kind, EventKind::kWater);  // ties: water before installed
  EXPECT_EQ(ev[3].kind, EventKind::kInstalled);
  for (std::size_t i = 1; i < ev.size(); ++i) EXPECT_LE(ev[i - 1].at, ev[i].at);
}

TEST_F(HistoryStoreTest, RecentAndSearch) {
  HistoryStore store(db_path);
  const TimePoint t0 = makeUtc(2020, 1, 1);
  auto a = hugin("10-01-01", t0);
  auto b = hugin("10-01-02", t0 + days{1});
  b.payload_note = "HISAS 1032 100% synthetic_aperture";
  auto c = hugin("20-05-01", t0 + days{2});
  c.vehicle_key = "slocum49";
  c.vehicle_name = "Slocum glider 49";
  c.area = "Bedford Basin";
  for (const auto& x : {a, b, c}) store.addConfiguration(x);
  store.addWaterCondition("10-01-01", water(t0 + days{30}, 4, 35));  // a is now the most recent
  const auto recent = store.recentConfigurations(2);
  ASSERT_EQ(recent.size(), 2u);
  EXPECT_EQ(recent[0].configuration.config_id, "10-01-01");
  EXPECT_EQ(recent[0].last_activity, t0 + days{30});
  EXPECT_EQ(recent[1].configuration.config_id, "20-05-01");
  EXPECT_EQ(store.search("10-01").size(), 2u);
  EXPECT_EQ(store.search("hisas").size(), 1u);
  EXPECT_EQ(store.search("bedford").at(0).config_id, "20-05-01");
  EXPECT_EQ(store.search("slocum").size(), 1u);
  EXPECT_EQ(store.search("100%").size(), 1u);  // '%' is literal, not a wildcard
  EXPECT_EQ(store.search("_").size(), 1u);     // only b's note contains '_'
  EXPECT_TRUE(store.search("nothing like this").empty());
}

TEST_F(HistoryStoreTest, FailedSaveLeavesNothingBehind) {
  HistoryStore store(db_path);
  const TimePoint t0 = makeUtc(2020, 1, 1);
  store.addConfiguration(hugin("1-1-1", t0));
  Mission m;
  m.imported_at = t0;
  m.file_path = "a.log";
  m.sha256 = sha256Hex("a");
  AnalysisResult a;
  a.at = t0;
  // The water is invalid (salinity 60): the mission and analysis saved before it must vanish.
  EXPECT_THROW(store.savePostMission("1-1-1", m, a, water(t0, 4, 60)), InputError);
  EXPECT_TRUE(store.history("1-1-1").empty());
  // An exception thrown by the caller inside an outer transaction rolls back too.
  try {
    Transaction tx(store.database());
    store.addWaterCondition("1-1-1", water(t0, 4, 35));
    throw std::runtime_error("operator cancelled");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(store.history("1-1-1").empty());
  EXPECT_EQ(store.integrityCheck(), "ok");
}

TEST_F(HistoryStoreTest, DuplicateMissionAndCrossConfigurationLinksAreRefused) {
  HistoryStore store(db_path);
  const TimePoint t0 = makeUtc(2020, 1, 1);
  store.addConfiguration(hugin("1-1-1", t0));
  store.addConfiguration(hugin("1-1-2", t0));
  test::writeAll(dir.file("m.log"), "depth,pitch\n10,0.5\n");
  const RecordId id = store.importMissionFile("1-1-1", dir.file("m.log"), {{"rows", 1}}, t0);
  test::writeAll(dir.file("copy.log"), "depth,pitch\n10,0.5\n");
  try {
    store.importMissionFile("1-1-1", dir.file("copy.log"), {}, t0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("m.log"), std::string::npos) << e.what();
  }
  // The same log may belong to another configuration, but an analysis of
  // 1-1-1's mission cannot be filed under 1-1-2.
  AnalysisResult a;
  a.at = t0;
  a.mission_id = id;
  EXPECT_THROW(store.addAnalysisResult("1-1-2", a), InputError);
  EXPECT_NO_THROW(store.addAnalysisResult("1-1-1", a));
  EXPECT_THROW(store.addConfiguration(hugin("1-1-1", t0)), InputError);
  EXPECT_THROW(store.addConfiguration(hugin("1-1", t0)), InputError);
  EXPECT_THROW(store.addWaterCondition("9-9-9", water(t0, 4, 35)), InputError);
  InstalledState bad = installed(t0, 4.8, 0, 0, 0);
  bad.points[0].pieces_kg = {2.4, 1.2};  // 3.6 kg of pieces for 4.8 kg
  EXPECT_THROW(store.addInstalledState("1-1-1", bad), InputError);
}

}  // namespace auv
