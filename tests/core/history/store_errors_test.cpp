// Opening problems must name the file and say what to do, and must never
// damage what is already in the file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/input_error.h"
#include "history/sha256.h"
#include "store_fixture.h"

namespace auv {
using test::hugin;
using test::water;

namespace {
std::string openError(const std::string& path, const std::vector<Migration>* steps = nullptr) {
  try {
    if (steps)
      HistoryStore s(path, *steps);
    else
      HistoryStore s(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}
}  // namespace

class HistoryOpenTest : public test::StoreTest {};

TEST_F(HistoryOpenTest, FileThatIsNotSqliteIsRefusedAndLeftAlone) {
  std::string text;
  for (int i = 0; i < 200; ++i) text += "Config\tDate\tType\tArea\n";  // e.g. a ballasting file
  test::writeAll(db_path, text);
  const std::string msg = openError(db_path);
  EXPECT_TRUE(contains(msg, db_path)) << msg;
  EXPECT_TRUE(contains(msg, "not a SQLite database")) << msg;
  EXPECT_TRUE(contains(msg, "choose another file")) << msg;
  EXPECT_EQ(test::readAll(db_path), text);
}

TEST_F(HistoryOpenTest, NewerSchemaIsRefusedAndLeftAlone) {
  {
    HistoryStore store(db_path);
    store.addConfiguration(hugin("1-2-3", makeUtc(2014, 4, 4)));
    store.database().exec("PRAGMA user_version = 7", "test: pretend a newer program wrote it");
  }
  const std::string before = sha256OfFile(db_path);
  const std::string msg = openError(db_path);
  EXPECT_TRUE(contains(msg, db_path)) << msg;
  EXPECT_TRUE(contains(msg, "newer auvballast (schema version 7; this program knows up to 5)")) << msg;
  EXPECT_TRUE(contains(msg, "update auvballast")) << msg;
  EXPECT_EQ(sha256OfFile(db_path), before);
}

TEST_F(HistoryOpenTest, ReadOnlyOrMissingLocationIsNamed) {
  // /proc refuses new files even to root, so this is a real read-only place.
  const std::string proc_path = "/proc/auvballast-history-test.db";
  std::string msg = openError(proc_path);
  EXPECT_TRUE(contains(msg, proc_path)) << msg;
  EXPECT_TRUE(contains(msg, "read-only or not permitted")) << msg;
  EXPECT_TRUE(contains(msg, "choose a writable folder")) << msg;

  const std::string missing = dir.file("no/such/folder/history.db");
  msg = openError(missing);
  EXPECT_TRUE(contains(msg, "no/such/folder")) << msg;
  EXPECT_TRUE(contains(msg, "does not exist")) << msg;

  if (geteuid() != 0) {  // permissions do not bind root
    const std::string ro_dir = dir.file("ro");
    ASSERT_EQ(mkdir(ro_dir.c_str(), 0555), 0);
    msg = openError(ro_dir + "/history.db");
    EXPECT_TRUE(contains(msg, "read-only or not permitted")) << msg;
  }
}

TEST_F(HistoryOpenTest, OlderSchemaIsMigratedKeepingTheData) {
  const std::vector<Migration> v1_only = {standardMigrations().front()};
  {
    HistoryStore old(db_path, v1_only);
    EXPECT_EQ(old.schemaVersion(), 1);
    old.addConfiguration(hugin("1-2-3", makeUtc(2014, 4, 4, 15, 28)));
    old.addWaterCondition("1-2-3", water(makeUtc(2014, 4, 4, 15, 34), 6.545581, 34.4975));
    EXPECT_EQ(old.database().queryInt(
                  "SELECT count(*) FROM sqlite_schema WHERE name = 'installed_states'"),
              0);
  }
  HistoryStore store(db_path);
  EXPECT_EQ(store.schemaVersion(), latestSchemaVersion());
  const auto s = store.lastState("1-2-3", makeUtc(2014, 4, 5));
  ASSERT_TRUE(s && s->last_temperature);
  EXPECT_DOUBLE_EQ(*s->last_temperature->temperature_degC, 6.545581);
  EXPECT_NO_THROW(store.addInstalledState("1-2-3", test::installed(makeUtc(2014, 4, 5), 0, 0, 19.2, 19.2)));
  EXPECT_EQ(store.integrityCheck(), "ok");
}

// A history written before BG was a configuration field (schema 3) opens
// with every record intact, BG "not measured", and then keeps a BG.
TEST_F(HistoryOpenTest, SchemaThreeGainsBgKeepingEveryRecord) {
  const std::vector<Migration> up_to_v3(standardMigrations().begin(), standardMigrations().begin() + 3);
  {
    HistoryStore old(db_path, up_to_v3);
    ASSERT_EQ(old.schemaVersion(), 3);
    Configuration c = hugin("02-01-01", makeUtc(2014, 4, 4, 15, 28));
    c.payload_note = "HISAS";
    c.area = "Horten";
    old.addConfiguration(c);
    old.addWaterCondition("02-01-01", water(makeUtc(2014, 4, 4, 15, 34), 6.545581, 34.4975));
    old.addInstalledState("02-01-01", test::installed(makeUtc(2014, 4, 5), 0, 0, 19.2, 19.2));
    EXPECT_EQ(old.database().queryInt("SELECT count(*) FROM pragma_table_info('configurations') WHERE name = 'bg_mm'"), 0);
  }
  HistoryStore store(db_path);
  EXPECT_EQ(store.schemaVersion(), latestSchemaVersion());
  auto c = store.configuration("02-01-01");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->payload_note, "HISAS");
  EXPECT_EQ(c->area, "Horten");
  EXPECT_EQ(c->created_at, makeUtc(2014, 4, 4, 15, 28));
  EXPECT_FALSE(c->bg_mm);  // not measured before
  const auto s = store.lastState("02-01-01", makeUtc(2014, 4, 6));
  ASSERT_TRUE(s && s->last_temperature && s->installed);
  EXPECT_DOUBLE_EQ(*s->last_temperature->temperature_degC, 6.545581);
  ASSERT_EQ(s->installed->points.size(), 4u);
  EXPECT_DOUBLE_EQ(s->installed->points[2].mass_kg, 19.2);
  EXPECT_EQ(s->configuration.payload_note, "HISAS");

  store.setConfigurationBg("02-01-01", 21.5);
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-01")->bg_mm, 21.5);
  try {
    store.setConfigurationBg("02-01-01", -3.0);
    ADD_FAILURE() << "a negative BG was stored";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "BG (CG below CB)")) << e.what();
  }
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-01")->bg_mm, 21.5);  // unchanged by the refusal
  store.setConfigurationBg("02-01-01", std::nullopt);
  EXPECT_FALSE(store.configuration("02-01-01")->bg_mm);
  EXPECT_EQ(store.integrityCheck(), "ok");
}

// A history written before the pitch sensor's level check was a
// configuration field (schema 4) opens with its BG kept and the check "not
// checked"; then the check is kept, refused outside 0..5 deg, and cleared.
TEST_F(HistoryOpenTest, SchemaFourGainsThePitchLevelCheckKeepingBg) {
  const std::vector<Migration> up_to_v4(standardMigrations().begin(), standardMigrations().begin() + 4);
  {
    HistoryStore old(db_path, up_to_v4);
    ASSERT_EQ(old.schemaVersion(), 4);
    Configuration c = hugin("02-01-01", makeUtc(2014, 4, 4, 15, 28));
    c.bg_mm = 21.5;
    c.pitch_level_check_deg = 0.1;  // this file has no place for it: not stored
    old.addConfiguration(c);
    EXPECT_DOUBLE_EQ(*old.configuration("02-01-01")->bg_mm, 21.5);
    EXPECT_FALSE(old.configuration("02-01-01")->pitch_level_check_deg);
  }
  HistoryStore store(db_path);
  EXPECT_EQ(store.schemaVersion(), 5);
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-01")->bg_mm, 21.5);
  EXPECT_FALSE(store.configuration("02-01-01")->pitch_level_check_deg);  // not checked before

  store.setConfigurationPitchLevelCheck("02-01-01", 0.1);
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-01")->pitch_level_check_deg, 0.1);
  for (const double bad : {0.0, -0.2, 7.0}) {
    try {
      store.setConfigurationPitchLevelCheck("02-01-01", bad);
      ADD_FAILURE() << "a level check of " << bad << " deg was stored";
    } catch (const InputError& e) {
      EXPECT_TRUE(contains(e.what(), "pitch sensor level check")) << e.what();
      EXPECT_TRUE(contains(e.what(), "0..5 deg")) << e.what();
    }
  }
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-01")->pitch_level_check_deg, 0.1);  // unchanged by the refusals
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-01")->bg_mm, 21.5);
  store.setConfigurationPitchLevelCheck("02-01-01", std::nullopt);
  EXPECT_FALSE(store.configuration("02-01-01")->pitch_level_check_deg);

  // A new configuration keeps both from the start.
  Configuration n = hugin("02-01-02", makeUtc(2014, 5, 1));
  n.bg_mm = 19.0;
  n.pitch_level_check_deg = 0.25;
  store.addConfiguration(n);
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-02")->bg_mm, 19.0);
  EXPECT_DOUBLE_EQ(*store.configuration("02-01-02")->pitch_level_check_deg, 0.25);
  Configuration bad = hugin("02-01-03", makeUtc(2014, 5, 1));
  bad.pitch_level_check_deg = 9.0;
  EXPECT_THROW(store.addConfiguration(bad), InputError);
  EXPECT_FALSE(store.configuration("02-01-03"));  // nothing half-written
  EXPECT_EQ(store.integrityCheck(), "ok");
}

TEST_F(HistoryOpenTest, FailedMigrationLeavesTheFileByteIdentical) {
  {
    HistoryStore old(db_path, {standardMigrations().front()});
    old.addConfiguration(hugin("1-2-3", makeUtc(2014, 4, 4, 15, 28)));
  }
  const std::string before = sha256OfFile(db_path);
  // Steps 2 to 5 (real) and 6 (injected: writes, then fails) are pending.
  std::vector<Migration> steps = standardMigrations();
  steps.push_back({6, "injected failure", [](Database& db) {
                     db.exec("CREATE TABLE half_done(x); INSERT INTO half_done VALUES (1);",
                             "test step");
                     throw std::runtime_error("injected failure after a partial write");
                   }});
  const std::string msg = openError(db_path, &steps);
  EXPECT_TRUE(contains(msg, db_path)) << msg;
  EXPECT_TRUE(contains(msg, "from schema version 1 to 6: step 6 (injected failure) failed")) << msg;
  EXPECT_TRUE(contains(msg, "left exactly as it was")) << msg;
  EXPECT_EQ(sha256OfFile(db_path), before);

  // A step whose SQL is wrong fails the same way.
  std::vector<Migration> bad_sql = {standardMigrations().front(),
                                    {2, "bad sql", [](Database& db) {
                                       db.exec("CREATE TABLE ok_part(x); CREATE TABLE (", "test");
                                     }}};
  EXPECT_TRUE(contains(openError(db_path, &bad_sql), "step 2 (bad sql) failed"));
  EXPECT_EQ(sha256OfFile(db_path), before);

  HistoryStore store(db_path);  // the real program still opens and upgrades it
  EXPECT_EQ(store.schemaVersion(), latestSchemaVersion());
  EXPECT_EQ(store.database().queryInt(
                "SELECT count(*) FROM sqlite_schema WHERE name IN ('half_done', 'ok_part')"),
            0);
  EXPECT_TRUE(store.configuration("1-2-3"));
}

}  // namespace auv
